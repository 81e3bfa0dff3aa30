#!/usr/bin/env python3
"""roslaunch XML (ROS 1): parse and start a file of 20 nodes, launcher against roslaunch.

The nodes are one package's executable (`sleeper`, a shell script that execs `sleep`), so the
figure is the launch system's own cost: the time from the command to the 20th `sleep`
running. roslaunch (Debian's ROS 1: `apt-get install python3-roslaunch ros-base`) runs with
its master already up (roscore started first, not timed), which favours it; without ROS 1
installed the benchmark says so and times launcher alone.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import time
from pathlib import Path

import psutil
from _harness import launcher_cmd, summary, table, wait_for, workdir

NODES = 20


def workspace(folder: Path, count: int = NODES) -> Path:
    """A package with a `sleeper` executable, and a launch file of `count` nodes of it."""
    package = folder / "src" / "bench_nodes"
    (package / "scripts").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<?xml version="1.0"?><package format="2"><name>bench_nodes</name><version>0.0.1'
        '</version><description>b</description><maintainer email="a@b.c">a</maintainer>'
        "<license>MIT</license></package>\n")
    script = package / "scripts" / "sleeper"
    script.write_text("#!/bin/sh\nexec sleep 120\n")
    script.chmod(0o755)
    nodes = "\n".join(f'  <node name="n{i}" pkg="bench_nodes" type="sleeper"/>'
                      for i in range(count))
    path = folder / f"nodes{count}.launch"
    path.write_text(f"<launch>\n  <arg name=\"unused\" default=\"1\"/>\n{nodes}\n</launch>\n")
    return path


def sleeping(root: int) -> int:
    try:
        return sum(1 for p in psutil.Process(root).children(recursive=True)
                   if p.name() == "sleep")
    except psutil.Error:
        return 0


def time_to_running(argv: list[str], env: dict[str, str], count: int = NODES) -> float:
    """Seconds from the command to its `count`-th node running."""
    begin = time.perf_counter()
    proc = subprocess.Popen(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)
    try:
        end = wait_for(lambda: sleeping(proc.pid) >= count, timeout=120, step=0.002)
    finally:
        os.killpg(proc.pid, 2)
        try:
            proc.wait(30)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, 9)
            proc.wait()
    return end - begin


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=5)
    runs = parser.parse_args().runs
    folder = workdir()
    path = workspace(folder)
    ours_env = {**os.environ, "LAUNCHER_PACKAGE_PATH": str(folder / "src"),
                "LAUNCHER_RUN_DIR": str(folder / "run")}
    ours = [time_to_running([*launcher_cmd(), "launch", str(path)], ours_env)
            for _ in range(runs)]
    rows = [(f"roslaunch XML, {NODES} nodes: launcher, last running", "",
             summary(ours))]
    if shutil.which("roslaunch") and shutil.which("roscore"):
        ros_env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
        ros_env.update(ROS_PACKAGE_PATH=str(folder / "src"), ROS_HOME=str(folder / "ros"),
                       ROS_MASTER_URI="http://127.0.0.1:11411", PATH="/usr/bin:/bin")
        core = subprocess.Popen(["roscore", "-p", "11411"], env=ros_env,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)
        try:
            time.sleep(3)
            theirs = [time_to_running(["roslaunch", str(path)], ros_env) for _ in range(runs)]
        finally:
            os.killpg(core.pid, 2)
            core.wait(20)
        ratio = sorted(ours)[len(ours) // 2] / sorted(theirs)[len(theirs) // 2]
        rows += [(f"roslaunch XML, {NODES} nodes: roslaunch, last running", "",
                  summary(theirs)),
                 ("launcher / roslaunch (medians, same run)", "<= 0.3", f"{ratio:.2f}")]
    else:
        rows.append(("roslaunch (ROS 1) not installed: no ratio", "<= 0.3", "not measured"))
    table("roslaunch XML (seconds)", rows)


if __name__ == "__main__":
    main()
