"""A URDF's visual meshes gathered into the converter's `assets/` folder.

Each mesh is copied to `assets/full/<stem><suffix>` (a stem two files share gets `__1`, `__2`,
as the converter names them) and the URDF's filename pointed there. MuJoCo reads STL and OBJ
itself, so those are the model as they are (mujoco_ros2_control's converter turns them into
OBJ through trimesh and splits them by material with obj2mjcf; the colour of a URDF visual is
its geom's rgba either way). A folder of meshes made before (`-a`, obj2mjcf's layout
`full/<stem>/<stem>.obj`) is used where it has the mesh. COLLADA (`.dae`) needs converting:
that is done by trimesh, installed apart (apart.py). A mesh named in `decompose_mesh` is
also cut into its convex parts, in `assets/decomposed/<stem>/` (CoACD, apart.py).
"""

from __future__ import annotations

import shutil
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError

FULL = "full"  # the converter's folder of whole (not decomposed) meshes
DECOMPOSED = "decomposed"
READ_BY_MUJOCO = (".stl", ".obj", ".msh")


def gather(robot: ET.Element, assets: Path, resolve: Callable[[str], Path],
           pregenerated: Path | None, tools: Any,
           decompose: dict[str, str]) -> dict[str, list[str]]:
    """Copy every `<mesh filename>` into `assets/full/` and point the URDF at the copy
    (a path relative to `assets/`, the compiler's assetdir); the meshes to decompose, by
    stem, with their parts' paths under `assets/`."""
    if assets.exists():
        shutil.rmtree(assets)
    (assets / FULL).mkdir(parents=True)
    stems: dict[str, str] = {}  # stem -> the URI that has it
    done: dict[str, str] = {}  # URI -> its path under assets/
    parts: dict[str, list[str]] = {}
    for mesh in robot.iter("mesh"):
        uri = mesh.get("filename", "")
        if not uri:
            continue
        if uri not in done:
            stem = _stem(uri, stems)
            done[uri] = _copy(uri, stem, assets, resolve, pregenerated, tools)
            threshold = decompose.get(stem, decompose.get(Path(uri).stem))
            if threshold is not None:
                folder = assets / DECOMPOSED / stem
                parts[stem] = [f"{DECOMPOSED}/{stem}/{name}" for name in
                               tools.decompose(assets / done[uri], folder, stem, threshold)]
        mesh.set("filename", done[uri])
    return parts


def _stem(uri: str, stems: dict[str, str]) -> str:
    original = stem = Path(uri).stem
    counter = 0
    while stems.get(stem, uri) != uri:
        counter += 1
        stem = f"{original}__{counter}"
    stems[stem] = uri
    return stem


def _copy(uri: str, stem: str, assets: Path, resolve: Callable[[str], Path],
          pregenerated: Path | None, tools: Any) -> str:
    made = pregenerated / FULL / stem / f"{stem}.obj" if pregenerated else None
    if made is not None and made.is_file():
        shutil.copy2(made, assets / FULL / f"{stem}.obj")
        return f"{FULL}/{stem}.obj"
    source = resolve(uri)
    suffix = source.suffix.lower()
    if suffix in READ_BY_MUJOCO:
        shutil.copy2(source, assets / FULL / f"{stem}{suffix}")
        return f"{FULL}/{stem}{suffix}"
    if suffix == ".dae":
        tools.dae_to_obj(source, assets / FULL / f"{stem}.obj")
        return f"{FULL}/{stem}.obj"
    raise LaunchError(f"mesh '{uri}': a {suffix or 'suffix-less'} file; the converter takes "
                      "STL, OBJ, MSH (MuJoCo reads them) and COLLADA (.dae, converted to OBJ)")
