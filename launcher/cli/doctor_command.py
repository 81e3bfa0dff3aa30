"""`launcher doctor`: check the install and the workspace, and say what to fix.

Each check prints one line, `ok`, `note` (works, with a remark) or `FAIL` (with what to do);
the exit status is 1 when any failed. Nothing is changed and nothing is left running.
"""

from __future__ import annotations

import argparse
import importlib.metadata
import os
import subprocess
import sys
from collections.abc import Callable

OK, NOTE, FAIL = "ok", "note", "FAIL"
Check = tuple[str, str, str]  # (status, what, detail or fix)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """(no arguments: the checks are the report)"""


def python() -> Check:
    version = ".".join(map(str, sys.version_info[:3]))
    return OK, f"Python {version}", sys.executable  # (an older one cannot run launcher)


def _version(package: str) -> str:
    try:
        return importlib.metadata.version(package)
    except importlib.metadata.PackageNotFoundError:
        return ""


def mujoco() -> Check:
    version = _version("mujoco")
    if not version:
        return FAIL, "MuJoCo", "not installed: sh hooks/bootstrap.sh test (or pip install mujoco)"
    gl = os.environ.get("MUJOCO_GL", "")
    detail = f"{version}; GL back-end: {gl or 'none set (the sim needs none; pictures use EGL)'}"
    return OK, "MuJoCo", detail


def egl() -> Check:
    """Pictures (`launcher sim snapshot`) render offscreen with EGL: try it, in a child."""
    probe = ("import os; os.environ['MUJOCO_GL'] = 'egl'\n"
             "import mujoco; c = mujoco.GLContext(64, 64); c.make_current(); c.free()\n")
    try:
        done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                              timeout=60)
    except subprocess.TimeoutExpired:
        return FAIL, "EGL (pictures)", "an EGL context took over 60 s to make"
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        return FAIL, "EGL (pictures)", (f"{last}; install Mesa's EGL: apt-get install libegl1 "
                                        "libegl-mesa0 libgl1-mesa-dri")
    return OK, "EGL (pictures)", "an offscreen context works"


def zenoh() -> Check:
    version = _version("eclipse-zenoh")
    if not version:
        return FAIL, "Zenoh", "not installed: sh hooks/bootstrap.sh test (or pip install " \
                              "eclipse-zenoh)"
    return OK, "Zenoh", version


def router() -> Check:
    from launcher.bus import discovery

    try:
        sock = discovery.socket_path(os.environ)
        endpoints = discovery.explicit_endpoints(os.environ)
    except Exception as exc:  # noqa: BLE001 - a bad setting is what this check reports
        return FAIL, "the graph's router", f"{exc}"
    domain = discovery.domain_id(os.environ)
    if endpoints:
        return OK, "the graph's router", f"LAUNCHER_ROUTER: {', '.join(endpoints)}"
    if discovery.answers(sock):
        return OK, "the graph's router", f"running for domain {domain} at {sock}"
    return NOTE, "the graph's router", (f"none running for domain {domain}: the first launch "
                                        "or node starts one (or: launcher router)")


def packages() -> tuple[Check, object | None]:
    from launcher.packages.index import PackageIndex

    try:
        index = PackageIndex.from_environment(os.environ)
    except Exception as exc:  # noqa: BLE001 - what this check reports
        return (FAIL, "package path", str(exc)), None
    roots = [f"{r.path} ({r.origin})" for r in index.roots
             if r.origin != "builtin" and r.path.is_dir()]
    missing = [str(r.path) for r in index.roots if r.origin == "workspace"
               and not r.path.is_dir()]
    count = len(list(index))
    if missing:
        return (FAIL, "package path", f"LAUNCHER_PACKAGE_PATH names {', '.join(missing)}, "
                                      "which is not a folder"), index
    if index.warnings:
        return (FAIL, "package path", "; ".join(index.warnings)), index
    if not roots:
        return (NOTE, "package path", f"{count} packages, launcher's own only: add a "
                                      "workspace with LAUNCHER_PACKAGE_PATH=/path/to/ws/src "
                                      "(or source its install/setup.sh, AMENT_PREFIX_PATH)"),\
            index
    return (OK, "package path", f"{count} packages under {', '.join(roots)}"), index


def hooks(index: object | None) -> Check:
    if index is None:
        return NOTE, "environment hooks", "not run: the package path failed"
    from launcher.cli.workspace import hooked_environment

    try:
        after = hooked_environment(index, dict(os.environ))  # type: ignore[arg-type]
    except Exception as exc:  # noqa: BLE001 - what this check reports (with its file:line)
        return FAIL, "environment hooks", str(exc)
    changed = sorted(k for k in after if after[k] != os.environ.get(k))
    return OK, "environment hooks", f"they set {', '.join(changed) or 'nothing'}"


def real_ros() -> Check:
    from launcher import compat

    found = compat.real_node_apis(dict(os.environ))
    if found:
        return NOTE, "ROS install", f"{found} (in your own shell, a real one wins)"
    return OK, "ROS install", "none needed: launcher's rclpy, rospy and messages are used"


def commands() -> Check:
    """Which `ros2`, `gz`, `roslaunch`, … this shell runs: launcher's, or a real one (which
    always wins: launcher's come last on PATH)."""
    import shutil

    from launcher import compat

    ours, real, absent = [], [], []
    for name in compat.command_names():
        found = shutil.which(name)
        if found is None:
            absent.append(name)
        elif os.path.dirname(os.path.abspath(found)) == compat.COMMANDS:
            ours.append(name)
        else:
            real.append(f"{name} → {found}")
    parts = []
    if real:
        parts.append(f"real: {', '.join(real)}")
    if ours:
        parts.append(f"launcher's: {', '.join(ours)}")
    if absent:
        parts.append(f"not on PATH: {', '.join(absent)} (. hooks/setup.sh puts them there)")
    return (NOTE if absent else OK), "commands", "; ".join(parts)


def build_tools() -> Check:
    """colcon and CMake for `colcon build`, installed apart under .venv/tools by the set-up."""
    from launcher.packages import build

    try:
        build.check_installed()
    except build.BuildError as exc:
        return NOTE, "build tools", str(exc)
    return OK, "build tools", f"colcon and CMake under {build.TOOLS}"


def run(args: argparse.Namespace) -> int:
    checks: list[Callable[[], Check]] = [python, mujoco, egl, zenoh, router, real_ros,
                                         commands, build_tools]
    results = [check() for check in checks]
    package_check, index = packages()
    results += [package_check, hooks(index)]
    width = max(len(what) for _, what, _ in results)
    for status, what, detail in results:
        print(f"{status:<4}  {what:<{width}}  {detail}")
    failed = [what for status, what, _ in results if status == FAIL]
    if failed:
        print(f"\n{len(failed)} to fix: {', '.join(failed)}")
        return 1
    print("\nall good")
    return 0
