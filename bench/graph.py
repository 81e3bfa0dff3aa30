#!/usr/bin/env python3
"""A graph of nodes against real ROS 2 (issue 57): N rclpy talkers, each publishing at 10 Hz on
a topic of its own, and one listener that says when it has heard every talker. The same
Python launch file is run by `launcher launch` (its rclpy) and by real ros2 launch with real
rclpy (the Kilted wheels on Fast DDS, installed apart as the fidelity oracle installs them:
`--ros2 DIR`, default .fidelity/ros2), in the same run, one after the other.

Figures, for each N:
- launch → every talker heard (s): from the launch command's start to the listener's having
  heard the last talker (its own clock: one machine);
- memory of one talker (USS, MiB, the median of the talkers), once every talker is heard;
- the graph's idle CPU (% of one core: every process of the launch, the launcher included,
  over `--idle` seconds once every talker is heard).
A graph that has not heard every talker within `--limit` seconds says how many it heard.
Then the messages' figures, against the same real ROS 2 (bench/graph_messages.py): latency
p50 and p99 at 64 B and 1 MB, throughput, and a 1 kHz timer's jitter (`--no-messages`: not).

    python bench/graph.py [--sizes 10,50,100] [--ros2 DIR] [--limit 300] [--only launcher]
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import graph_messages
import psutil
from _harness import launcher_cmd, stop, table

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))  # (real ros2 launch, run as the fidelity oracle runs it)
from tests.fidelity.record import ros2_tool  # noqa: E402

TARGETS = {10: "≤ 0.25×", 50: "≤ 2 s", 100: "≤ 4 s"}  # (the issue's, for launcher)

TALKER = """
import sys
import rclpy
from std_msgs.msg import String

rclpy.init()
index = sys.argv[1]
node = rclpy.create_node(f"talker_{index}")
publisher = node.create_publisher(String, f"/talker_{index}", 10)
message = String(data=index)
node.create_timer(0.1, lambda: publisher.publish(message))
try:
    rclpy.spin(node)
except BaseException:  # (Ctrl-C, or the context shut down: the bench's end)
    pass
"""
LISTENER = """
import sys
import time
import rclpy
from std_msgs.msg import String

rclpy.init()
count = int(sys.argv[1])
node = rclpy.create_node("listener")
heard = set()


def hear(message):
    if message.data in heard:
        return
    heard.add(message.data)
    print(f"HEARD {len(heard)} {time.time():.6f}", flush=True)


subscriptions = [node.create_subscription(String, f"/talker_{i}", hear, 10)
                 for i in range(count)]
try:
    rclpy.spin(node)
except BaseException:
    pass
"""
LAUNCH = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess

COUNT = {count}
PYTHON = {python!r}
HERE = {folder!r}


def generate_launch_description():
    talkers = [ExecuteProcess(cmd=[PYTHON, HERE + "/talker.py", str(i)], name=f"talker_{{i}}")
               for i in range(COUNT)]
    listener = ExecuteProcess(cmd=[PYTHON, HERE + "/listener.py", str(COUNT)], name="listener",
                              output="screen")
    return LaunchDescription([listener, *talkers])
"""


def tree(pid: int) -> list[psutil.Process]:
    try:
        root = psutil.Process(pid)
        return [root, *root.children(recursive=True)]
    except psutil.Error:
        return []


def cpu_seconds(processes: list[psutil.Process]) -> float:
    total = 0.0
    for proc in processes:
        try:
            times = proc.cpu_times()
            total += times.user + times.system
        except psutil.Error:
            continue
    return total


def one(argv: list[str], env: dict[str, str], count: int, limit: float,
        idle: float) -> dict[str, float | str]:
    """Start the launch, wait for every talker to be heard, measure, stop it."""
    began = time.time()
    proc = subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, start_new_session=True)
    heard = [0, 0.0]  # (talkers heard, when the last was)
    done = threading.Event()

    def read() -> None:
        for line in proc.stdout:  # type: ignore[union-attr]
            at = line.find("HEARD ")
            if at >= 0:
                words = line[at:].split()
                heard[:] = [int(words[1]), float(words[2])]
                if heard[0] == count:
                    done.set()
        done.set()  # (its end: the launch is over)

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    result: dict[str, float | str] = {}
    processes = tree(proc.pid)
    try:
        done.wait(limit)
        processes = tree(proc.pid)  # (what to end after: the launch's, before it is reaped)
        if heard[0] < count:
            result["heard"] = f"{heard[0]} of {count} in {time.time() - began:.0f} s"
            return result
        result["heard"] = heard[1] - began
        talkers = [p for p in processes
                   if any(word.endswith("talker.py") for word in safe_cmdline(p))]
        uss = [p.memory_full_info().uss for p in talkers if alive(p)]
        result["uss"] = statistics.median(uss) / 2**20 if uss else float("nan")
        before, at = cpu_seconds(processes), time.monotonic()
        time.sleep(idle)
        result["idle"] = 100 * (cpu_seconds(processes) - before) / (time.monotonic() - at)
        return result
    finally:
        stop(proc, 60.0)  # (ros2 launch with 100 nodes takes its time)
        for left in processes[1:]:  # (nothing should be: said by the other benchmarks)
            if alive(left):
                left.kill()


def safe_cmdline(proc: psutil.Process) -> list[str]:
    try:
        return proc.cmdline()
    except psutil.Error:
        return []


def alive(proc: psutil.Process) -> bool:
    try:
        return proc.status() != psutil.STATUS_ZOMBIE
    except psutil.Error:
        return False


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="10,50,100")
    parser.add_argument("--ros2", type=Path, default=REPO / ".fidelity" / "ros2")
    parser.add_argument("--limit", type=float, default=300.0,
                        help="seconds a graph has to hear every talker")
    parser.add_argument("--idle", type=float, default=5.0)
    parser.add_argument("--only", choices=("launcher", "ros2"), default=None)
    parser.add_argument("--no-messages", action="store_true",
                        help="the graph's start only, not the messages' figures")
    args = parser.parse_args()
    signal.signal(signal.SIGINT, signal.default_int_handler)  # (the launches get it at default)
    sizes = [int(n) for n in args.sizes.split(",")]
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-graph-"))
    (folder / "talker.py").write_text(TALKER)
    (folder / "listener.py").write_text(LISTENER)
    base = {k: v for k, v in os.environ.items()
            if not k.startswith(("ROS_", "AMENT_", "RMW_", "LAUNCHER_ROUTER"))}
    base.update(LAUNCHER_LOG_DIR=str(folder / "log"), LAUNCHER_RUN_DIR=str(folder / "run"),
                ROS_LOG_DIR=str(folder / "roslog"), ROS_HOME=str(folder / "roshome"))
    logs = ("ROS_LOG_DIR", "ROS_HOME")
    ros2_python = args.ros2 / "bin" / "python"
    tools = {}
    if args.only != "ros2":
        tools["launcher"] = (sys.executable, lambda path: [*launcher_cmd(), "launch", "-n",
                                                           str(path)], base)
    if args.only != "launcher" and ros2_python.exists():
        real = ros2_tool(args.ros2)  # (as the fidelity oracle runs it: its own domain)
        tools["ros2 launch"] = (str(ros2_python), lambda path: [*real.command, str(path)],
                                {**real.env, **{k: base[k] for k in logs}})
    results: dict[tuple[str, int], dict[str, float | str]] = {}
    messages: dict[str, dict[str, dict[str, float] | str]] = {who: {} for who in tools}
    graph_messages.write_probes(folder)
    try:
        for count in sizes:
            for who, (python, argv, env) in tools.items():
                path = folder / f"{who.split()[0]}_{count}.launch.py"
                path.write_text(LAUNCH.format(count=count, python=python, folder=str(folder)))
                results[who, count] = one(argv(path), env, count, args.limit, args.idle)
                print(f"{who}, {count} talkers: {results[who, count]}", flush=True)
        for name in graph_messages.PROBES if not args.no_messages else ():
            for who, (python, argv, env) in tools.items():
                messages[who][name] = graph_messages.probe(argv, python, env, folder, name,
                                                           who.split()[0])
                print(f"{who}, {name}: {messages[who][name]}", flush=True)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    rows = []
    for count in sizes:
        ours, theirs = results.get(("launcher", count), {}), results.get(("ros2 launch", count),
                                                                         {})
        for who, got in (("launcher", ours), ("ros2 launch", theirs)):
            if not got:
                continue
            heard = got["heard"]
            rows += [
                (f"{count} talkers, {who}: launch → every talker heard (s)",
                 TARGETS.get(count, "-") if who == "launcher" and count != 10 else "-",
                 f"{heard:.2f}" if isinstance(heard, float) else str(heard)),
                (f"{count} talkers, {who}: one talker's memory (USS, MiB)", "-",
                 f"{got['uss']:.1f}" if "uss" in got else "-"),
                (f"{count} talkers, {who}: idle CPU (% of one core)", "-",
                 f"{got['idle']:.0f}" if "idle" in got else "-"),
            ]
        if isinstance(ours.get("heard"), float) and isinstance(theirs.get("heard"), float):
            rows.append((f"{count} talkers: launcher / ros2 launch, every talker heard",
                         TARGETS[count] if count == 10 else "-",
                         f"{ours['heard'] / theirs['heard']:.2f}"))
        if "uss" in ours and "uss" in theirs:
            rows.append((f"{count} talkers: launcher / ros2 launch, one talker's memory",
                         "≤ 0.4×", f"{ours['uss'] / theirs['uss']:.2f}"))
    rows += graph_messages.rows(messages)
    if "ros2 launch" not in tools and args.only != "launcher":
        rows.append(("ros2 launch", "-", f"not installed at {args.ros2}: no anchor this run"))
    table("A graph of rclpy talkers and one listener, against real ROS 2", rows)


if __name__ == "__main__":
    main()
