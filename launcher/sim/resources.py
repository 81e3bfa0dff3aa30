"""Finding worlds, models and meshes: the resource path, `model://` and `package://` URIs.

MUJOCO_SIM_RESOURCE_PATH is the analogue of GZ_SIM_RESOURCE_PATH: colon-separated folders
searched for worlds (by file name) and models (`model://NAME` is the folder NAME in one of
them). A model folder holds `model.config`, whose `<mjcf>`, `<urdf>` or `<sdf>` element names
the model file (the course's layout). `package://pkg/…` resolves through the package index.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from collections.abc import Mapping
from pathlib import Path

from launcher.errors import LaunchError, did_you_mean

RESOURCE_PATH = "MUJOCO_SIM_RESOURCE_PATH"
BUILTIN_WORLDS = Path(__file__).resolve().parent.parent / "builtin" / "mujoco_sim" / "worlds"


class ResourceNotFound(LaunchError):
    pass


def resource_dirs(environ: Mapping[str, str] | None = None) -> list[Path]:
    env = os.environ if environ is None else environ
    return [Path(p).expanduser() for p in env.get(RESOURCE_PATH, "").split(os.pathsep) if p]


def find_world(name: str, environ: Mapping[str, str] | None = None) -> Path:
    """A world as a path, then in each resource folder, then among the built-in worlds."""
    searched: list[str] = []
    candidate = Path(name).expanduser()
    if candidate.is_file():
        return candidate.resolve()
    searched.append(f"the path {candidate.resolve()}")
    if not candidate.is_absolute():
        for folder in resource_dirs(environ):
            if (folder / name).is_file():
                return (folder / name).resolve()
            searched.append(f"{folder} ({RESOURCE_PATH})")
        for suffix in ("", ".xml", ".xml.j2"):
            if (BUILTIN_WORLDS / f"{name}{suffix}").is_file():
                return BUILTIN_WORLDS / f"{name}{suffix}"
        searched.append(f"the built-in worlds ({', '.join(builtin_worlds())})")
    if not resource_dirs(environ):
        searched.append(f"{RESOURCE_PATH} is not set")
    known = [p.name for d in resource_dirs(environ) if d.is_dir() for p in d.iterdir()]
    raise ResourceNotFound(f"world '{name}' not found; searched:\n  " + "\n  ".join(searched)
                           + did_you_mean(name, known + builtin_worlds()))


def builtin_worlds() -> list[str]:
    return sorted(p.name for p in BUILTIN_WORLDS.glob("*.xml*"))


def find_model(name: str, environ: Mapping[str, str] | None = None) -> Path:
    """The folder of `model://NAME`."""
    folders = resource_dirs(environ)
    for folder in folders:
        if (folder / name).is_dir():
            return folder / name
    where = ", ".join(str(f) for f in folders) or f"nowhere: {RESOURCE_PATH} is not set"
    known = [p.name for d in folders if d.is_dir() for p in d.iterdir() if p.is_dir()]
    raise ResourceNotFound(f"model '{name}' (model://{name}) not found in {RESOURCE_PATH}: "
                           f"{where}{did_you_mean(name, known)}")


def model_file(folder: Path) -> Path:
    """The model file a model folder's model.config names (or its only model file)."""
    config = folder / "model.config"
    if config.is_file():
        try:
            root = ET.parse(config).getroot()
        except ET.ParseError as exc:
            raise LaunchError(f"{config}:{exc.position[0]}:{exc.position[1]}: "
                              f"model.config is not valid XML: {exc}") from None
        for tag in ("mjcf", "urdf", "sdf"):
            element = root.find(tag)
            if element is not None and (element.text or "").strip():
                path = folder / element.text.strip()
                if not path.is_file():
                    raise ResourceNotFound(f"{config}: <{tag}> names '{element.text.strip()}'"
                                           f", which is not in {folder}")
                return path
        raise LaunchError(f"{config}: expected an <mjcf>, <urdf> or <sdf> element naming "
                          "the model file")
    found = sorted(p for p in folder.iterdir() if p.suffix in (".xml", ".urdf"))
    if len(found) == 1:
        return found[0]
    raise ResourceNotFound(f"model folder {folder} has no model.config")


def resolve_uri(uri: str, base: Path | None, packages: object | None = None,
                environ: Mapping[str, str] | None = None) -> Path:
    """A file for a mesh or model URI: package://, model://, file://, absolute or relative."""
    if uri.startswith("package://"):
        package, _, rest = uri[len("package://"):].partition("/")
        if packages is None:
            from launcher.packages.index import PackageIndex

            packages = PackageIndex.from_environment(environ)
        try:
            root = packages.share(package)  # type: ignore[attr-defined]
        except LaunchError as exc:
            raise ResourceNotFound(f"'{uri}': {exc}") from None
        path = Path(root) / rest
        where = f"package '{package}' at {root}"
    elif uri.startswith("model://"):
        name, _, rest = uri[len("model://"):].partition("/")
        folder = find_model(name, environ)
        path = folder / rest if rest else model_file(folder)
        where = f"model folder {folder}"
    else:
        raw = uri[len("file://"):] if uri.startswith("file://") else uri
        path = Path(raw).expanduser()
        if not path.is_absolute():
            path = (base or Path.cwd()) / path
        where = f"{path.parent}"
    if not path.exists():
        raise ResourceNotFound(f"'{uri}' not found: looked for {path} (in {where})")
    return path.resolve()
