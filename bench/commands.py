#!/usr/bin/env python3
"""The commands users type by their own names (issue 34), each against its reference in the
same run.

- `ros2 topic list` and `rostopic list` on a running graph (a router and a talker), run as the
  shell runs them (launcher's compat/bin scripts on PATH), against `python -c pass` with the
  same interpreter: the ratio of medians (target ≤ 3 each).
- `colcon build` of the demo workspace's four packages (packages/, given an ament_cmake
  CMakeLists.txt each that installs their folders) from clean: seconds (reported).
- `roslaunch` of a file of 100 nodes (a package's shell script that execs `sleep`) to the
  100th running, through launcher's `roslaunch`; against Debian's roslaunch (its master up
  first, untimed) where it is installed (target ≤ 0.35 of it), else the figure alone.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _harness import start_router, summary, table
from roslaunch import time_to_running, workspace

REPO = Path(__file__).resolve().parent.parent
COMMANDS = REPO / "launcher" / "compat" / "bin"
NODES = 100
DEMO_PACKAGES = ("robot_application", "robot_bringup", "robot_description", "robot_gazebo")
CMAKE = """cmake_minimum_required(VERSION 3.8)
project({name})
find_package(ament_cmake REQUIRED)
install(DIRECTORY {folders} DESTINATION share/${{PROJECT_NAME}})
ament_package()
"""
EXPORT = """  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
"""


def timed(argv: list[str], env: dict[str, str], runs: int) -> list[float]:
    found = []
    for _ in range(runs):
        begin = time.perf_counter()
        subprocess.run(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       check=True)
        found.append(time.perf_counter() - begin)
    return found


def median(values: list[float]) -> float:
    return sorted(values)[len(values) // 2]


def listing(runs: int) -> list[tuple[str, str, str]]:
    env, router = start_router()
    env = {**env, "PATH": f"{Path(sys.executable).parent}:/usr/bin:/bin:{COMMANDS}"}
    talker = subprocess.Popen([str(COMMANDS / "rostopic"), "pub", "-r", "10", "/chatter",
                               "std_msgs/String", "hi"], env=env, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)
    try:
        time.sleep(2.0)
        rows = []
        baseline, ros2, ros1 = [], [], []
        for _ in range(runs):  # interleaved: the machine's noise falls on all three
            baseline += timed([sys.executable, "-c", "pass"], env, 1)
            ros2 += timed([str(COMMANDS / "ros2"), "topic", "list"], env, 1)
            ros1 += timed([str(COMMANDS / "rostopic"), "list"], env, 1)
        rows.append(("python -c pass (baseline)", "report", summary(baseline)))
        rows.append(("ros2 topic list, running graph", "report", summary(ros2)))
        rows.append(("rostopic list, running graph", "report", summary(ros1)))
        rows.append(("ros2 topic list / baseline (medians)", "<= 3",
                     f"{median(ros2) / median(baseline):.2f}"))
        rows.append(("rostopic list / baseline (medians)", "<= 3",
                     f"{median(ros1) / median(baseline):.2f}"))
        return rows
    finally:
        talker.send_signal(2)
        talker.wait(10)
        router.send_signal(2)
        router.wait(10)


def colcon(runs: int) -> list[tuple[str, str, str]]:
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-colcon-"))
    for name in DEMO_PACKAGES:
        source = REPO / "packages" / name
        target = folder / "src" / name
        shutil.copytree(source, target)
        folders = " ".join(sorted(p.name for p in target.iterdir() if p.is_dir()))
        (target / "CMakeLists.txt").write_text(CMAKE.format(name=name, folders=folders))
        manifest = target / "package.xml"  # as an ament_cmake package's (and an email that
        text = manifest.read_text().replace("@localhost", "@example.com")  # catkin_pkg takes)
        if "<export>" in text:
            text = text.replace("<export>", "<buildtool_depend>ament_cmake</buildtool_depend>"
                                "\n  <export><build_type>ament_cmake</build_type>")
        else:
            text = text.replace("</package>", EXPORT + "</package>")
        manifest.write_text(text)
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}:/usr/bin:/bin:{COMMANDS}"}
    found = []
    for _ in range(runs):
        for name in ("build", "install", "log"):
            shutil.rmtree(folder / name, ignore_errors=True)
        begin = time.perf_counter()
        subprocess.run([str(COMMANDS / "colcon"), "build"], cwd=folder, env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        found.append(time.perf_counter() - begin)
    shutil.rmtree(folder, ignore_errors=True)
    return [(f"colcon build, the demo's {len(DEMO_PACKAGES)} packages from clean, s",
             "report", summary(found))]


def roslaunch(runs: int) -> list[tuple[str, str, str]]:
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-roslaunch-"))
    path = workspace(folder, NODES)
    ours_env = {**os.environ, "LAUNCHER_PACKAGE_PATH": str(folder / "src"),
                "LAUNCHER_RUN_DIR": str(folder / "run"),
                "PATH": f"{Path(sys.executable).parent}:/usr/bin:/bin:{COMMANDS}"}
    ours = [time_to_running([str(COMMANDS / "roslaunch"), str(path)], ours_env, NODES)
            for _ in range(runs)]
    rows = [(f"roslaunch, {NODES} nodes to all running: launcher's, s", "report",
             summary(ours))]
    real = shutil.which("roslaunch", path="/usr/bin") if shutil.which("roscore",
                                                                      path="/usr/bin") else None
    if real:
        ros_env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
        ros_env.update(ROS_PACKAGE_PATH=str(folder / "src"), ROS_HOME=str(folder / "ros"),
                       ROS_MASTER_URI="http://127.0.0.1:11412", PATH="/usr/bin:/bin")
        core = subprocess.Popen(["/usr/bin/roscore", "-p", "11412"], env=ros_env,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)
        try:
            time.sleep(3)
            theirs = [time_to_running([real, str(path)], ros_env, NODES)
                      for _ in range(runs)]
        finally:
            os.killpg(core.pid, 2)
            core.wait(20)
        rows += [(f"roslaunch, {NODES} nodes: Debian's roslaunch, s", "report",
                  summary(theirs)),
                 ("launcher's / Debian's roslaunch (medians, same run)", "<= 0.35",
                  f"{median(ours) / median(theirs):.2f}")]
    else:
        rows.append(("Debian's roslaunch not installed: no ratio", "<= 0.35", "not measured"))
    shutil.rmtree(folder, ignore_errors=True)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=9)
    runs = parser.parse_args().runs
    rows = listing(max(runs, 9)) + colcon(max(3, runs // 3)) + roslaunch(max(3, runs // 3))
    table("the users' own commands", rows)


if __name__ == "__main__":
    main()
