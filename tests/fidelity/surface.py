"""Record the public surface of the real packages: `python -m tests.fidelity.surface`.

The real packages are installed apart under .fidelity/ (as tests.fidelity.record installs
them for the corpus, never on anybody's PATH) and walked by surface_walk.py in their own
interpreter:

  * ROS 2: launch, launch_xml, launch_yaml, launch_ros, launch_testing, launch_testing_ros
    and launch_pytest from their sources (`--ros2-source DIR`: checkouts of ros2/launch and
    ros2/launch_ros as DIR/launch and DIR/launch_ros), with rclpy's Kilted wheels (rclpy,
    rcl_interfaces, lifecycle_msgs, ament_index_python);
  * ROS 1: Debian's rospy, actionlib, rostest, roslaunch and rosbag.

Each root package's record is written to surface/<root>.json, and the module tree of the
packages launcher shims to launcher/compat/layout.json (every module with its public names:
the modules that have no file of their own among the shims are made from it). Names that launch and
launch_ros added after their newest release are in surface/newer.json, read from the newest
sources by hand (the walk cannot install what is not released), in the same form.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

from tests.fidelity.record import install_ros1, install_ros2, say

HERE = Path(__file__).resolve().parent
SURFACE = HERE / "surface"
WALK = HERE / "surface_walk.py"
ROS2_ROOTS = ("launch", "launch_xml", "launch_yaml", "launch_ros", "launch_testing",
              "launch_testing_ros", "launch_pytest", "rclpy", "rcl_interfaces",
              "lifecycle_msgs", "ament_index_python")
ROS2_EXTRA_SOURCES = ("launch/launch_testing", "launch/launch_pytest",
                      "launch_ros/launch_testing_ros")
ROS2_EXTRA_WHEELS = ("pytest", "ros-std-msgs", "ros-rosgraph-msgs")
ROS1_ROOTS = ("rospy", "actionlib", "rostest", "roslaunch", "rosbag")
ROS1_EXTRA_DEBS = ("python3-rospy", "python3-actionlib", "python3-actionlib-msgs",
                   "python3-rostest", "python3-rosbag", "python3-roslz4", "python3-gnupg",
                   "python3-pycryptodome", "python3-rosunit", "python3-genmsg",
                   "python3-geometry-msgs", "python3-sensor-msgs", "python3-std-srvs",
                   "python3-topic-tools", "python3-roscpp-msg", "python3-rosnode")


def ros2_interpreter(oracle: Path, source: Path | None) -> tuple[list[str], dict[str, str]]:
    venv = install_ros2(oracle, source)
    marker = venv / "surface-extras"
    if not marker.exists():
        if source is None:
            sys.exit("surface: ROS 2 needs --ros2-source DIR once, to install launch_testing,"
                     " launch_testing_ros and launch_pytest")
        pip = [str(venv / "bin/python"), "-m", "pip", "install", "--quiet"]
        say("adding launch_testing, launch_testing_ros and launch_pytest")
        subprocess.run([*pip, *ROS2_EXTRA_WHEELS], check=True)
        for part in ROS2_EXTRA_SOURCES:
            subprocess.run([*pip, "--no-deps", str(source / part)], check=True)
        marker.write_text("")
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(("ROS_", "AMENT_", "LAUNCHER_", "PYTHON"))}
    env["AMENT_PREFIX_PATH"] = str(venv)
    return [str(venv / "bin/python")], env


def ros1_interpreter(oracle: Path) -> tuple[list[str], dict[str, str]]:
    root = install_ros1(oracle)
    marker = root / "surface-extras"
    if not marker.exists():
        debs = oracle / "ros1-debs"
        say("adding rospy, actionlib, rostest and rosbag")
        subprocess.run(["apt-get", "download", *ROS1_EXTRA_DEBS], cwd=debs, check=True)
        for deb in sorted(debs.glob("*.deb")):
            subprocess.run(["dpkg", "-x", str(deb), str(root)], check=True)
        marker.write_text("")
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(("ROS_", "AMENT_", "LAUNCHER_", "PYTHON"))}
    env.update(PYTHONPATH=str(root / "usr/lib/python3/dist-packages"),
               ROS_PACKAGE_PATH=str(root / "usr/share"), ROS_DISTRO="noetic")
    return ["/usr/bin/python3"], env


def walk(interpreter: list[str], env: dict[str, str], roots: tuple[str, ...]) -> None:
    say(f"walking {', '.join(roots)}")
    done = subprocess.run([*interpreter, str(WALK), *roots], env=env, check=True,
                          capture_output=True, text=True)
    record = json.loads(done.stdout)
    SURFACE.mkdir(exist_ok=True)
    for root, modules in record.items():
        errors = [name for name, module in modules.items() if "error" in module]
        names = sum(len(module.get("names", {})) for module in modules.values())
        (SURFACE / f"{root}.json").write_text(json.dumps(modules, indent=1, sort_keys=True)
                                              + "\n")
        say(f"{root}: {len(modules)} modules ({len(errors)} not importable there), "
            f"{names} names")


def write_layout() -> None:
    """launcher/compat/layout.json: {module: {public name: the module that defines it, or ""
    for one defined there or a constant}} of every importable recorded module of the packages
    that launcher shims."""
    from launcher.compat.finder import LAYOUT, LAYOUT_ROOTS

    def home(module: str, entry: dict) -> str:
        defined = entry.get("module") or ""
        return defined if defined != module and defined.split(".")[0] in LAYOUT_ROOTS else ""

    layout: dict[str, dict[str, str]] = {}
    newer = SURFACE / "newer.json"
    extra = json.loads(newer.read_text()) if newer.exists() else {}
    for root in LAYOUT_ROOTS:
        for module, entry in json.loads((SURFACE / f"{root}.json").read_text()).items():
            if "error" not in entry:
                layout[module] = {name: home(module, e) for name, e in entry["names"].items()}
    for module, names in extra.items():
        layout.setdefault(module, {}).update(
            {name: home(module, e) for name, e in names.items()})
    Path(LAYOUT).write_text(json.dumps(layout, indent=0, sort_keys=True) + "\n")
    say(f"wrote {LAYOUT}: {len(layout)} modules")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oracle", type=Path, default=HERE.parent.parent / ".fidelity")
    parser.add_argument("--ros2-source", type=Path)
    parser.add_argument("--only", choices=("ros1", "ros2", "layout"))
    options = parser.parse_args()
    if options.only == "layout":
        write_layout()
        return
    if options.only in (None, "ros2"):
        walk(*ros2_interpreter(options.oracle, options.ros2_source), ROS2_ROOTS)
    if options.only in (None, "ros1"):
        walk(*ros1_interpreter(options.oracle), ROS1_ROOTS)
    write_layout()


if __name__ == "__main__":
    main()
