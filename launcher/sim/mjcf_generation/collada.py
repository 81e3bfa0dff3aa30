"""COLLADA (`.dae`) meshes to OBJ, which MuJoCo reads, with trimesh installed apart.

MuJoCo reads no COLLADA. mujoco_ros2_control's `robot_description_to_mjcf.sh` installs trimesh
(and more) into a virtual environment of its own, `$ROS_HOME/ros2_control/.venv` (ROS_HOME
defaults to ~/.ros), and converts there. So does launcher, the first time a robot has a
COLLADA mesh, saying so; after that the environment is reused. trimesh and pycollada already
importable by launcher's own Python are used instead. The mesh is set Z-up first, as the
converter sets it (MuJoCo's z is up).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

from launcher.errors import LaunchError

PACKAGES = ("trimesh", "pycollada", "numpy")
CHECK = "import trimesh, collada"
CONVERT = ("import sys, trimesh; "
           "trimesh.load(sys.argv[1], force='mesh').export(sys.argv[2], include_color=True)")
INSTALL_TIMEOUT = 600.0  # s


def environment() -> Path:
    """Where the converter's own environment is: `$ROS_HOME/ros2_control/.venv`."""
    home = os.environ.get("ROS_HOME") or str(Path.home() / ".ros")
    return Path(home) / "ros2_control" / ".venv"


def converter(say: Callable[[str], None]) -> Callable[[Path, Path], None]:
    """A `dae_to_obj(source, target)` that finds (or installs, once) its Python when first
    called."""
    found: list[str] = []

    def dae_to_obj(source: Path, target: Path) -> None:
        if not found:
            found.append(python_with_trimesh(say))
        with tempfile.TemporaryDirectory() as folder:
            z_up = Path(folder) / source.name
            z_up.write_text(_z_up(source.read_text(errors="replace")))
            for image in _images(source):
                (Path(folder) / image.name).write_bytes(image.read_bytes())
            done = subprocess.run([found[0], "-c", CONVERT, str(z_up), str(target)],
                                  capture_output=True, text=True)
        if done.returncode != 0:
            lines = done.stderr.strip().splitlines()
            raise LaunchError(f"mesh {source}: trimesh could not convert it to OBJ: "
                              f"{lines[-1] if lines else 'exit ' + str(done.returncode)}")
        say(f"converted {source} to {target.name}")

    return dae_to_obj


def python_with_trimesh(say: Callable[[str], None]) -> str:
    if subprocess.run([sys.executable, "-c", CHECK], capture_output=True).returncode == 0:
        return sys.executable
    venv = environment()
    python = venv / "bin" / "python"
    if python.exists() and subprocess.run([str(python), "-c", CHECK],
                                          capture_output=True).returncode == 0:
        return str(python)
    say(f"COLLADA meshes need trimesh and pycollada to become OBJ (MuJoCo reads no .dae): "
        f"installing {', '.join(PACKAGES)} into {venv} (once; later runs reuse it)")
    steps = [[sys.executable, "-m", "venv", str(venv)],
             [str(python), "-m", "pip", "install", "--no-input", "--disable-pip-version-check",
              "-q", *PACKAGES]]
    for step in steps:
        try:
            done = subprocess.run(step, capture_output=True, text=True,
                                  timeout=INSTALL_TIMEOUT)
        except subprocess.TimeoutExpired:
            raise LaunchError(f"installing trimesh into {venv} took over "
                              f"{INSTALL_TIMEOUT:g} s; stopped") from None
        if done.returncode != 0:
            lines = (done.stderr or done.stdout).strip().splitlines()
            raise LaunchError(f"could not install trimesh into {venv} (needed for COLLADA "
                              f"meshes): {lines[-1] if lines else 'exit ' + str(done.returncode)}")
    return str(python)


def _z_up(text: str) -> str:
    if re.search(r"<up_axis>", text):
        return re.sub(r"<up_axis>\s*\w+\s*</up_axis>", "<up_axis>Z_UP</up_axis>", text)
    return re.sub(r"(<asset>)", r"\1<up_axis>Z_UP</up_axis>", text, count=1)


def _images(source: Path) -> list[Path]:
    """The textures a COLLADA file names (copied beside its Z-up copy)."""
    text = source.read_text(errors="replace")
    found = []
    for name in re.findall(r"<init_from>\s*([^<]+?)\s*</init_from>", text):
        path = (source.parent / name).resolve()
        if path.suffix.lower() in (".png", ".jpg", ".jpeg") and path.is_file():
            found.append(path)
    return found
