"""A graph's messages against real ROS 2 (issue 57; bench/graph.py runs it): one rclpy sender
and one rclpy receiver in a launch, and a node with a 1 kHz timer, each launch run by
`launcher launch` (its rclpy, its bus) and by real ros2 launch (real rclpy on Fast DDS), the
same Python files both times.

- latency: the sender stamps each std_msgs/String with its wall clock (one machine), the
  receiver takes the difference; p50 and p99 in µs, at 64 B (200 Hz, 5 s) and 1 MB (20 Hz,
  5 s), the first 10% left out (discovery settling);
- throughput: the sender publishes as fast as it can for 2 s (keep last 100, reliable, ROS 2's
  default QoS); what the receiver gets per second, at 64 B (messages/s) and 1 MB (MB/s);
- a 1 kHz timer's jitter: |period − 1 ms| of each callback over 3 s, p50 and p99 in µs, and
  the callbacks it ran per second.
"""

from __future__ import annotations

import json
import subprocess
import threading
from collections.abc import Callable
from pathlib import Path

from _harness import stop

SENDER = """
import sys
import time
import rclpy
from std_msgs.msg import String

rclpy.init()
size, rate, seconds = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
node = rclpy.create_node("sender")
publisher = node.create_publisher(String, "/probe", 100)
pad = "x" * max(0, size - 20)
try:
    while publisher.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.05)
    time.sleep(1.0)  # (both sides settled)
    start = time.monotonic()
    sent = 0
    while time.monotonic() - start < seconds:
        publisher.publish(String(data=f"{time.time_ns():020d}" + pad))
        sent += 1
        if rate > 0:
            time.sleep(max(0.0, start + sent / rate - time.monotonic()))
    rclpy.spin(node)
except BaseException:  # (Ctrl-C: the bench's end)
    pass
"""
RECEIVER = """
import json
import time
import rclpy
from std_msgs.msg import String

rclpy.init()
node = rclpy.create_node("receiver")
latencies, arrivals, sizes = [], [], []


def hear(message):
    now = time.time_ns()
    latencies.append(now - int(message.data[:20]))
    arrivals.append(now)
    sizes.append(len(message.data))


def check():
    if arrivals and time.time_ns() - arrivals[-1] > 1.5e9:
        kept = latencies[len(latencies) // 10:]
        kept.sort()
        span = (arrivals[-1] - arrivals[0]) / 1e9
        print("RESULT " + json.dumps({
            "count": len(arrivals),
            "p50": kept[len(kept) // 2] / 1e3, "p99": kept[int(len(kept) * 0.99)] / 1e3,
            "per_second": (len(arrivals) - 1) / span if span else 0.0,
            "bytes_per_second": sum(sizes[1:]) / span if span else 0.0}), flush=True)
        timer.cancel()


subscription = node.create_subscription(String, "/probe", hear, 100)
timer = node.create_timer(0.2, check)
try:
    rclpy.spin(node)
except BaseException:
    pass
"""
TIMER = """
import json
import time
import rclpy

rclpy.init()
node = rclpy.create_node("ticker")
ticks = []


def tick():
    ticks.append(time.monotonic_ns())
    if ticks[-1] - ticks[0] >= 3e9:
        timer.cancel()
        periods = sorted(abs(b - a - 1_000_000) for a, b in zip(ticks, ticks[1:]))
        print("RESULT " + json.dumps({
            "p50": periods[len(periods) // 2] / 1e3,
            "p99": periods[int(len(periods) * 0.99)] / 1e3,
            "per_second": (len(ticks) - 1) / ((ticks[-1] - ticks[0]) / 1e9)}), flush=True)


timer = node.create_timer(0.001, tick)
try:
    rclpy.spin(node)
except BaseException:
    pass
"""
LAUNCH = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess

PYTHON = {python!r}


def generate_launch_description():
    return LaunchDescription([ExecuteProcess(cmd=[PYTHON, *command], output="screen")
                              for command in {commands!r}])
"""
# name: (the launch's commands, as [script, args…], relative to the folder)
PROBES = {
    "latency 64 B": [["receiver.py"], ["sender.py", "64", "200", "5"]],
    "latency 1 MB": [["receiver.py"], ["sender.py", str(2**20), "20", "5"]],
    "throughput 64 B": [["receiver.py"], ["sender.py", "64", "0", "2"]],
    "throughput 1 MB": [["receiver.py"], ["sender.py", str(2**20), "0", "2"]],
    "timer 1 kHz": [["timer.py"]],
}


def write_probes(folder: Path) -> None:
    for name, text in (("sender.py", SENDER), ("receiver.py", RECEIVER), ("timer.py", TIMER)):
        (folder / name).write_text(text)


def probe(argv: Callable[[Path], list[str]], python: str, env: dict[str, str], folder: Path,
          name: str, tag: str, limit: float = 120.0) -> dict[str, float] | str:
    """One probe's launch (its file named by `tag` and the probe), run until its RESULT line:
    the figures, or why there are none."""
    commands = [[str(folder / words[0]), *words[1:]] for words in PROBES[name]]
    path = folder / f"{tag}_{name.replace(' ', '_')}.launch.py"
    path.write_text(LAUNCH.format(python=python, commands=commands))
    proc = subprocess.Popen(argv(path), env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, start_new_session=True)
    found: list[dict[str, float]] = []
    done = threading.Event()

    def read() -> None:
        for line in proc.stdout:  # type: ignore[union-attr]
            at = line.find("RESULT ")
            if at >= 0 and not found:
                found.append(json.loads(line[at + 7:]))
                done.set()
        done.set()

    threading.Thread(target=read, daemon=True).start()
    try:
        done.wait(limit)
    finally:
        stop(proc, 60.0)  # (ros2 launch with 100 nodes takes its time)
    return found[0] if found else f"no result in {limit:.0f} s"


def rows(results: dict[str, dict[str, dict[str, float] | str]]) -> list[tuple[str, str, str]]:
    """The table's rows: each tool's figures, and launcher's against ros2 launch's."""
    out = []
    figures = {
        "latency 64 B": (("p50", "µs"), ("p99", "µs")),
        "latency 1 MB": (("p50", "µs"), ("p99", "µs")),
        "throughput 64 B": (("per_second", "messages/s"),),
        "throughput 1 MB": (("bytes_per_second", "MB/s"),),
        "timer 1 kHz": (("p50", "µs off 1 ms"), ("p99", "µs off 1 ms"),
                        ("per_second", "callbacks/s")),
    }
    for name, wanted in figures.items():
        for field, unit in wanted:
            got = {}
            for who, by_probe in results.items():
                value = by_probe.get(name)
                if isinstance(value, dict):
                    number = value[field] / 1e6 if unit == "MB/s" else value[field]
                    got[who] = number
                    out.append((f"{name}, {who}: {field} ({unit})", "-", f"{number:.1f}"))
                elif value is not None:
                    out.append((f"{name}, {who}", "-", value))
            if len(got) == 2 and got.get("ros2 launch"):
                out.append((f"{name}: launcher / ros2 launch, {field}", "-",
                            f"{got['launcher'] / got['ros2 launch']:.2f}"))
    return out
