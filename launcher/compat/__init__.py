"""Shims so ROS Python code runs unchanged without ROS: `launch`, `launch_ros` and
`ament_index_python` (the last is what xacro's `$(find pkg)` imports), Gazebo's `gz` command
for launched processes, and for nodes `rclpy`, `rospy` and the message packages (finder.py,
installed at interpreter start by site/sitecustomize.py).

The shims folder goes on sys.path (and PYTHONPATH for children) only where the real modules
are not installed; they answer from a package index built from the environment (its search
paths and the working folder).
"""

from __future__ import annotations

import os
import sys

from launcher.compat.finder import SHIMMED, SHIMS

TYPE_CHECKING = False  # (typing.TYPE_CHECKING without importing typing)

if TYPE_CHECKING:  # imported by every node's start (the finder): nothing more than needed
    from collections.abc import MutableMapping

COMMANDS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin")  # gz, ros2, …
SITE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "site")  # node APIs' hook


def _real_installed(name: str) -> bool:
    import importlib.util

    if any(os.path.abspath(p) == SHIMS for p in sys.path):
        return False
    return importlib.util.find_spec(name) is not None


def installed_apart(name: str) -> bool:
    """A real `name` (not launcher's shim of it) is importable here: its own plugins and
    tools then run, and launcher's stand aside."""
    import importlib.util

    spec = importlib.util.find_spec(name)
    return spec is not None and spec.origin is not None and not spec.origin.startswith(SHIMS)


def enable_in_process() -> None:
    """Make the shims importable here, for modules that have no real version installed, and
    the message packages (a Python launch file imports lifecycle_msgs' Transition ids; the
    finder comes last, so a real one wins)."""
    if SHIMS not in sys.path and not all(_real_installed(name) for name in SHIMMED):
        sys.path.append(SHIMS)
    from launcher.compat.finder import install

    install()


def enable_for_children(environment: MutableMapping[str, str]) -> None:
    """Make the shims importable in child processes (xacro as a command, user nodes), and
    rclpy, rospy and the message packages wherever no real ones are installed."""
    old = environment.get("PYTHONPATH", "")
    parts = old.split(os.pathsep) if old else []
    if SITE not in parts:
        parts.append(SITE)
    if SHIMS not in parts and not _real_installed("ament_index_python"):
        parts.append(SHIMS)
    environment["PYTHONPATH"] = os.pathsep.join(parts)


def node_apis_for_shell(environment: MutableMapping[str, str]) -> None:
    """What `launcher env` adds for the user's shell: rclpy, rospy and message modules (each
    only where no real one is installed: the finder comes last)."""
    old = environment.get("PYTHONPATH", "")
    parts = old.split(os.pathsep) if old else []
    if SITE not in parts:
        environment["PYTHONPATH"] = os.pathsep.join([*parts, SITE])


def commands_for_children(environment: MutableMapping[str, str]) -> None:
    """Append launcher's `gz`, `ros2` and ROS 1's tools to the children's PATH: last, so a
    real Gazebo's `gz` or ROS's tools earlier on PATH win."""
    path = environment.get("PATH", "")
    parts = path.split(os.pathsep) if path else []
    if COMMANDS not in parts:
        environment["PATH"] = os.pathsep.join([*parts, COMMANDS])


def commands_for_shell(environment: MutableMapping[str, str]) -> None:
    """What `launcher env` adds for the user's shell: `ros2`, `gz`, ROS 1's tools, last on
    PATH, so the user's own (a real ROS or Gazebo) earlier on PATH wins."""
    commands_for_children(environment)


def command_names() -> list[str]:
    """The names launcher provides as shell commands (compat/bin)."""
    return sorted(name for name in os.listdir(COMMANDS) if not name.startswith("."))


def real_node_apis(environment: MutableMapping[str, str]) -> str:
    """A note when a real rclpy or rospy is installed where the children look (their
    PYTHONPATH, then this interpreter's path): theirs wins, and how to choose ours."""
    from launcher.compat.finder import CHOICE_VARIABLE

    if environment.get(CHOICE_VARIABLE) == "launcher":
        return ""
    extra = [p for p in environment.get("PYTHONPATH", "").split(os.pathsep) if p]
    found = []
    for name in ("rclpy", "rospy"):
        for folder in [*extra, *sys.path]:
            if folder and folder != SHIMS and os.path.isfile(
                    os.path.join(folder, name, "__init__.py")) and \
                    not folder.startswith(os.path.dirname(SHIMS)):
                found.append(f"{name} in {folder}")
                break
    if not found:
        return ""
    return (f"a real ROS client library is installed ({', '.join(found)}): nodes use it, "
            f"and it does not join launcher's graph; set {CHOICE_VARIABLE}=launcher to "
            "use launcher's instead")
