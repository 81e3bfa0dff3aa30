"""The environment every test runs in, built by the suite instead of taken from the machine.

- PATH: the venv's `bin`, then the system's base folders, with no real ROS or Gazebo tool
  reachable. A folder holding one (Debian's ROS 1 tools live in /usr/bin, beside `sh`) is
  replaced by a mirror of it: a folder of links to everything in it but those tools. A test
  that checks "a real install wins" puts its own stand-in on PATH.
- `../shared`: the material that is not the project's (public worlds, launch files and
  examples; the user's seed documents). A clone has none beside it; a test that needs it
  skips, naming what is missing, unless LAUNCHER_REQUIRE_EXTERNAL=1 (CI) makes that a failure.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SHARED = REPO.parent / "shared"
REQUIRE_EXTERNAL = "LAUNCHER_REQUIRE_EXTERNAL"

# What a real ROS 1, ROS 2 or Gazebo install puts on PATH: the suite must never reach them
REAL_TOOLS = ("ros2", "rosparam", "roscore", "roslaunch", "rosrun", "rostopic", "rosservice",
              "rosnode", "rosbag", "rosmsg", "rossrv", "rospack", "gz", "ign", "gazebo",
              "colcon", "catkin_make")
BASE_FOLDERS = ("/usr/local/sbin", "/usr/local/bin", "/usr/sbin", "/usr/bin", "/sbin", "/bin")


def shared(*parts: str) -> Path:
    """A file or folder of ../shared; skips the test (fails it in CI) when it is missing."""
    path = SHARED.joinpath(*parts)
    if path.exists():
        return path
    message = (f"needs {path}, which this clone lacks (the public test material and seed "
               f"documents live in ../shared beside the repo, not in it)")
    if os.environ.get(REQUIRE_EXTERNAL) == "1":
        pytest.fail(f"{message}; {REQUIRE_EXTERNAL}=1 makes that a failure")
    pytest.skip(message)


def is_ours(folder: Path) -> bool:
    """The repo's and the venv's folders hold launcher's own commands."""
    try:
        resolved = folder.resolve()
    except OSError:
        return False
    return resolved == REPO or REPO in resolved.parents


def real_tools_in(folder: Path) -> list[str]:
    if is_ours(folder):
        return []
    return [name for name in REAL_TOOLS if os.access(folder / name, os.X_OK)]


def clean_path(venv_bin: Path, mirrors: Path, folders: tuple[str, ...] = BASE_FOLDERS) -> str:
    """PATH for the suite: `venv_bin`, then `folders` that exist, each one holding a real
    ROS or Gazebo tool replaced by its mirror under `mirrors`."""
    found, seen = [str(venv_bin)], set()
    for name in folders:
        folder = Path(name)
        if not folder.is_dir() or folder.resolve() in seen:
            continue  # /bin → /usr/bin: the same folder once
        seen.add(folder.resolve())
        if real_tools_in(folder):
            folder = mirror(folder, mirrors / name.strip("/").replace("/", "_"))
        found.append(str(folder))
    return os.pathsep.join(found)


def mirror(folder: Path, into: Path) -> Path:
    """A folder of links to every entry of `folder` but the real tools."""
    into.mkdir(parents=True, exist_ok=True)
    for entry in folder.iterdir():
        if entry.name not in REAL_TOOLS and not (into / entry.name).exists():
            (into / entry.name).symlink_to(entry)
    return into
