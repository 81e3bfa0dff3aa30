"""Shims so ROS 2 Python code runs unchanged without ROS: `launch`, `launch_ros` and
`ament_index_python` (the last is what xacro's `$(find pkg)` imports), and Gazebo's `gz`
command for launched processes.

The shims folder goes on sys.path (and PYTHONPATH for children) only where the real modules
are not installed; they answer from a package index built from the environment (its search
paths and the working folder).
"""

from __future__ import annotations

import importlib.util
import os
import sys
from collections.abc import MutableMapping

SHIMS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "shims")
COMMANDS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin")  # gz
SHIMMED = ("ament_index_python", "launch", "launch_ros")


def _real_installed(name: str) -> bool:
    if any(os.path.abspath(p) == SHIMS for p in sys.path):
        return False
    return importlib.util.find_spec(name) is not None


def enable_in_process() -> None:
    """Make the shims importable here, for modules that have no real version installed."""
    if SHIMS not in sys.path and not all(_real_installed(name) for name in SHIMMED):
        sys.path.append(SHIMS)


def enable_for_children(environment: MutableMapping[str, str]) -> None:
    """Make the shims importable in child processes (xacro as a command, user nodes)."""
    if _real_installed("ament_index_python"):
        return
    old = environment.get("PYTHONPATH", "")
    parts = old.split(os.pathsep) if old else []
    if SHIMS not in parts:
        environment["PYTHONPATH"] = os.pathsep.join([*parts, SHIMS])


def commands_for_children(environment: MutableMapping[str, str]) -> None:
    """Append launcher's `gz` to the children's PATH: last, so a real Gazebo's `gz` earlier on
    PATH wins. The user's own shell never gets it (there it is `launcher gz`)."""
    path = environment.get("PATH", "")
    parts = path.split(os.pathsep) if path else []
    if COMMANDS not in parts:
        environment["PATH"] = os.pathsep.join([*parts, COMMANDS])
