"""The converter's tools that MuJoCo does not have, installed apart: trimesh (COLLADA meshes
to OBJ, which MuJoCo reads) and CoACD (`decompose_mesh`: a mesh's convex parts, so that it
collides as its shape and not as its hull).

mujoco_ros2_control's `robot_description_to_mjcf.sh` installs its tools into a virtual
environment of its own, `$ROS_HOME/ros2_control/.venv` (ROS_HOME defaults to ~/.ros), and so
does launcher, the first time a robot needs them, saying so (with the versions their
requirements pin); after that the environment is reused. Tools already importable by
launcher's own Python are used instead. A COLLADA mesh is set Z-up first, as the converter
sets it; CoACD runs with obj2mjcf's settings (seed 0: the same parts every time), and the
parts are named as obj2mjcf names them, `<mesh>_collision_<i>.obj`.
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

PACKAGES = ("trimesh==4.11.4", "pycollada", "coacd==1.0.7", "numpy")  # (their pins)
CHECK = "import trimesh, collada, coacd"
CONVERT = ("import sys, trimesh; "
           "trimesh.load(sys.argv[1], force='mesh').export(sys.argv[2], include_color=True)")
DECOMPOSE = """
import os, sys, coacd, trimesh
source, folder, stem, threshold = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
coacd.set_log_level("error")
whole = os.path.join(folder, stem + ".obj")  # (through OBJ, as the converter's pipeline goes)
trimesh.load(source, force="mesh").export(whole, include_color=True)
mesh = trimesh.load(whole, force="mesh")
os.remove(whole)
parts = coacd.run_coacd(coacd.Mesh(mesh.vertices, mesh.faces), threshold=threshold,
                        preprocess_resolution=50, max_convex_hull=-1, mcts_iterations=100,
                        mcts_max_depth=3, mcts_nodes=20, resolution=2000, pca=False, seed=0)
for index, (vertices, faces) in enumerate(parts):
    trimesh.Trimesh(vertices, faces).export(f"{folder}/{stem}_collision_{index}.obj")
print(len(parts))
"""
INSTALL_TIMEOUT = 600.0  # s


def environment() -> Path:
    """Where the converter's own environment is: `$ROS_HOME/ros2_control/.venv`."""
    home = os.environ.get("ROS_HOME") or str(Path.home() / ".ros")
    return Path(home) / "ros2_control" / ".venv"


class Tools:
    """The tools, their Python found (or installed, once) when first needed."""

    def __init__(self, say: Callable[[str], None]) -> None:
        self.say = say
        self._python = ""

    @property
    def python(self) -> str:
        if not self._python:
            self._python = python_with_tools(self.say)
        return self._python

    def dae_to_obj(self, source: Path, target: Path) -> None:
        with tempfile.TemporaryDirectory() as folder:
            z_up = Path(folder) / source.name
            z_up.write_text(_z_up(source.read_text(errors="replace")))
            for image in _images(source):
                (Path(folder) / image.name).write_bytes(image.read_bytes())
            self._run([CONVERT, str(z_up), str(target)], f"mesh {source}: trimesh could not "
                                                           "convert it to OBJ")
        self.say(f"converted {source} to {target.name}")

    def decompose(self, source: Path, folder: Path, stem: str, threshold: str) -> list[str]:
        """The convex parts of a mesh, written into `folder`: their file names."""
        folder.mkdir(parents=True, exist_ok=True)
        count = int(self._run([DECOMPOSE, str(source), str(folder), stem, threshold],
                              f"decompose_mesh '{stem}': CoACD failed").split()[-1])
        self.say(f"decomposed {stem} into {count} convex part(s) (threshold {threshold})")
        return [f"{stem}_collision_{index}.obj" for index in range(count)]

    def _run(self, arguments: list[str], failure: str) -> str:
        done = subprocess.run([self.python, "-c", *arguments], capture_output=True, text=True)
        if done.returncode != 0:
            lines = done.stderr.strip().splitlines() or [f"exit {done.returncode}"]
            raise LaunchError(f"{failure}: {lines[-1]}")
        return done.stdout


def python_with_tools(say: Callable[[str], None]) -> str:
    if subprocess.run([sys.executable, "-c", CHECK], capture_output=True).returncode == 0:
        return sys.executable
    venv = environment()
    python = venv / "bin" / "python"
    if python.exists() and subprocess.run([str(python), "-c", CHECK],
                                          capture_output=True).returncode == 0:
        return str(python)
    say(f"COLLADA meshes and decompose_mesh need trimesh, pycollada and coacd (MuJoCo has "
        f"neither): installing {', '.join(PACKAGES)} into {venv} (once; later runs reuse it)")
    steps = [[sys.executable, "-m", "venv", str(venv)],
             [str(python), "-m", "pip", "install", "--no-input", "--disable-pip-version-check",
              "-q", *PACKAGES]]
    for step in steps:
        try:
            done = subprocess.run(step, capture_output=True, text=True,
                                  timeout=INSTALL_TIMEOUT)
        except subprocess.TimeoutExpired:
            raise LaunchError(f"installing the converter's tools into {venv} took over "
                              f"{INSTALL_TIMEOUT:g} s; stopped") from None
        if done.returncode != 0:
            lines = (done.stderr or done.stdout).strip().splitlines()
            raise LaunchError(f"could not install the converter's tools into {venv}: "
                              f"{lines[-1] if lines else 'exit ' + str(done.returncode)}")
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
