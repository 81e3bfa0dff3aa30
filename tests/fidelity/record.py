"""Record what the real tools do with the corpus: `python -m tests.fidelity.record`.

The real tools are installed apart, under .fidelity/ in the checkout (ignored by git), never
on anybody's PATH:

  * ROS 1: Debian's roslaunch 1.15 (python3-roslaunch, python3-rosmaster, python3-rosparam
    and what they import), unpacked with `apt-get download` and `dpkg -x`, run by Debian's
    /usr/bin/python3 with that folder on PYTHONPATH. roscore.xml starts a `rosout` node: a
    stand-in that only waits takes its place (the corpus never logs through it).
  * ROS 2: a virtual environment with rclpy's Kilted wheels from PyPI (ros-rclpy,
    ros-rcl-interfaces, ros-lifecycle-msgs, ros-ament-index-python, an rmw) and launch,
    launch_xml, launch_yaml, launch_ros and ros2launch installed from their source: give
    `--ros2-source DIR`, a folder holding checkouts of ros2/launch (3.7.x) as DIR/launch and
    ros2/launch_ros (0.28.x) as DIR/launch_ros. composition_interfaces has no wheel: a
    stand-in module lets launch_ros import (the corpus's containers load nothing).

Each case runs through the real tool in a folder of its own; the outcome, normalised as the
test normalises launcher's, is written to expected/<case name>.json with the case's digest.
`--only TEXT` records the cases whose names contain TEXT; `--stale` those whose recording is
missing or was made of another text.
"""

from __future__ import annotations

import argparse
import itertools
import json
import os
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from tests.fidelity.corpus import Case, cases
from tests.fidelity.normalise import outcome
from tests.fidelity.runner import WORKSPACE, Tool, free_port

HERE = Path(__file__).resolve().parent
EXPECTED = HERE / "expected"
ROS1_DEBS = ("python3-roslaunch", "python3-rosmaster", "python3-rosparam", "python3-rosgraph",
             "python3-roslib", "python3-rospkg", "python3-catkin-pkg", "python3-catkin",
             "python3-rosclean", "python3-rosunit", "python3-defusedxml", "python3-netifaces",
             "python3-dateutil", "python3-pyparsing", "python3-docutils", "python3-six",
             "python3-rosgraph-msgs", "python3-std-msgs", "python3-genpy", "python3-genmsg")
ROS2_WHEELS = ("ros-rclpy", "ros-rcl-interfaces", "ros-lifecycle-msgs", "ros-ament-index-python",
               "ros-rmw-fastrtps-cpp", "osrf-pycommon", "lark", "pyyaml", "packaging",
               "importlib-metadata")
ROS2_SOURCES = ("launch/launch", "launch/launch_xml", "launch/launch_yaml",
                "launch_ros/launch_ros", "launch_ros/ros2launch")
DRIVER = '''import sys
from ros2launch.api import launch_a_launch_file
sys.exit(launch_a_launch_file(launch_file_path=sys.argv[1], launch_file_arguments=sys.argv[2:],
                              noninteractive=True))
'''


def say(text: str) -> None:
    print(f"[record] {text}", flush=True)


def install_ros1(oracle: Path) -> Path:
    root = oracle / "ros1"
    if (root / "usr/bin/roslaunch").exists():
        return root
    debs = oracle / "ros1-debs"
    debs.mkdir(parents=True, exist_ok=True)
    say(f"downloading Debian's roslaunch and what it imports into {debs}")
    subprocess.run(["apt-get", "download", *ROS1_DEBS], cwd=debs, check=True)
    for deb in sorted(debs.glob("*.deb")):
        subprocess.run(["dpkg", "-x", str(deb), str(root)], check=True)
    rosout = root / "ws/rosout"
    rosout.mkdir(parents=True, exist_ok=True)
    (rosout / "package.xml").write_text(
        '<package format="2"><name>rosout</name><version>0.0.0</version><description>'
        "stand-in</description><maintainer email='a@b.c'>a</maintainer><license>BSD"
        "</license></package>\n")
    (rosout / "rosout").write_text("#!/bin/sh\nexec sleep infinity\n")
    (rosout / "rosout").chmod(0o755)
    return root


def install_ros2(oracle: Path, source: Path | None) -> Path:
    venv = oracle / "ros2"
    if (venv / "drive.py").exists():
        return venv
    if source is None:
        sys.exit("record: ROS 2 needs --ros2-source DIR (checkouts of ros2/launch and "
                 "ros2/launch_ros as DIR/launch and DIR/launch_ros)")
    say(f"making {venv} with rclpy's wheels and launch from {source}")
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    pip = [str(venv / "bin/python"), "-m", "pip", "install", "--quiet"]
    subprocess.run([*pip, *ROS2_WHEELS], check=True)
    for part in ROS2_SOURCES:
        subprocess.run([*pip, "--no-deps", str(source / part)], check=True)
    site = next((venv / "lib").glob("python3*/site-packages"))
    stand_in = site / "composition_interfaces"
    stand_in.mkdir(exist_ok=True)
    (stand_in / "__init__.py").write_text("")
    (stand_in / "srv.py").write_text("class LoadNode:\n    class Request:\n        pass\n")
    (venv / "drive.py").write_text(DRIVER)
    return venv


def ros1_tool(root: Path) -> Tool:
    port = free_port()
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(("ROS_", "AMENT_", "LAUNCHER_", "PYTHON"))}
    env.update(PATH=f"{root / 'usr/bin'}:/usr/bin:/bin",
               PYTHONPATH=str(root / "usr/lib/python3/dist-packages"),
               ROS_PACKAGE_PATH=f"{WORKSPACE / 'src'}:{root / 'ws'}:{root / 'usr/share'}",
               ROS_ETC_DIR=str(root / "etc/ros"), ROS_DISTRO="noetic",
               ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_HOSTNAME="127.0.0.1")
    return Tool("roslaunch", ("/usr/bin/python3", str(root / "usr/bin/roslaunch"), "-p",
                              str(port)), env)


_DOMAINS = itertools.count()


def ros2_tool(venv: Path) -> Tool:
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(("ROS_", "AMENT_", "LAUNCHER_", "PYTHON"))}
    env.update(PATH=f"{venv / 'bin'}:/usr/bin:/bin",
               AMENT_PREFIX_PATH=f"{WORKSPACE / 'install'}:{venv}",
               # a domain per run: cases run side by side must not see each other's nodes
               ROS_DOMAIN_ID=str((os.getpid() + next(_DOMAINS)) % 200), ROS_LOCALHOST_ONLY="1")
    return Tool("ros2 launch", (str(venv / "bin/python"), str(venv / "drive.py")), env,
                python=(str(venv / "bin/python"),))


def record(case: Case, tool: Tool, scratch: Path) -> dict:
    folder = scratch / case.name.replace("/", "__")
    run = tool.run(case, folder)
    result = {"case": case.digest, "tool": tool.name, "outcome": outcome(run, folder,
                                                                       case.flavour)}
    path = EXPECTED / f"{case.name}.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(result, indent=1, sort_keys=True) + "\n")
    return result


def stale(case: Case) -> bool:
    path = EXPECTED / f"{case.name}.json"
    return not path.exists() or json.loads(path.read_text())["case"] != case.digest


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oracle", type=Path, default=HERE.parent.parent / ".fidelity")
    parser.add_argument("--ros2-source", type=Path)
    parser.add_argument("--only", default="")
    parser.add_argument("--stale", action="store_true")
    parser.add_argument("--jobs", type=int, default=4)
    options = parser.parse_args()
    chosen = [case for case in cases() if options.only in case.name
              and (not options.stale or stale(case))]
    tools = {}
    if any(case.flavour == "ros1" for case in chosen):
        root = install_ros1(options.oracle)
        tools["ros1"] = lambda: ros1_tool(root)
    if any(case.flavour == "ros2" for case in chosen):
        venv = install_ros2(options.oracle, options.ros2_source)
        tools["ros2"] = lambda: ros2_tool(venv)
    scratch = Path(tempfile.mkdtemp(prefix="fidelity-record-"))
    say(f"recording {len(chosen)} cases")
    try:
        with ThreadPoolExecutor(options.jobs) as pool:
            for case, result in zip(chosen, pool.map(
                    lambda c: record(c, tools[c.flavour](), scratch), chosen), strict=True):
                say(f"{case.name}: exit {result['outcome']['exit']}, "
                    f"{len(result['outcome']['starts'])} start(s)")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
