#!/usr/bin/env python3
"""Viewing benchmarks (issue 35): the foxglove bridge delivering the graph to Foxglove's own
client (@foxglove/ws-protocol on Node.js, tests/js/foxglove_client.js), through the token's
front, on a graph of the benchmark's own.

- a 640 × 480 rgb8 image published at 30 Hz: the rate one client receives (target ≥ 29 Hz),
  and each of three clients at once (reported); the bridge's CPU (% of one core) for each;
- a small message (std_msgs/Int32) at 1 kHz: the rate one client receives (target ≥ 990 Hz)
  and the bridge's CPU;
- the demo (launch_files/robot.launch.yaml, driving): the sim's real-time factor (sim time
  over wall time, from /clock) without a client, then while a client watches every channel
  (target ≥ 0.97), in the same run.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

import psutil
from _harness import start_router, table

REPO = Path(__file__).resolve().parent.parent
CLIENT = REPO / "tests" / "js" / "foxglove_client.js"
PUBLISHER = """
import sys, time
from launcher.bus.node import Node
from launcher.bus.types import registry
kind, topic, hz, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
node = Node("bench_publisher")
if kind == "image":
    message = node.message("sensor_msgs/msg/Image", height=480, width=640, encoding="rgb8",
                           step=640 * 3, data=[0] * (640 * 480 * 3))
    payload = registry().serialize(message, "sensor_msgs/msg/Image")
    publisher = node.create_publisher("sensor_msgs/msg/Image", topic)
else:
    payload = registry().serialize(node.message("std_msgs/msg/Int32", data=7),
                                   "std_msgs/msg/Int32")
    publisher = node.create_publisher("std_msgs/msg/Int32", topic)
period, start = 1.0 / hz, time.perf_counter()
sent = 0
while time.perf_counter() - start < seconds:
    publisher.publish_raw(payload)
    sent += 1
    wait = start + sent * period - time.perf_counter()
    if wait > 0.002:
        time.sleep(wait - 0.001)
    while start + sent * period > time.perf_counter():
        pass
node.destroy_node()
"""


def client(url: str, *steps: dict) -> subprocess.Popen:
    return subprocess.Popen([shutil.which("node") or "node", str(CLIENT), url,
                             json.dumps(list(steps))], stdout=subprocess.PIPE, text=True,
                            cwd=CLIENT.parent)


def lines_of(proc: subprocess.Popen) -> list[dict]:
    out, _ = proc.communicate(timeout=180)
    return [json.loads(line) for line in out.splitlines() if line.startswith("{")]


def bridge_process(root: int) -> psutil.Process:
    for proc in [psutil.Process(root), *psutil.Process(root).children(recursive=True)]:
        if "launcher.nodes.foxglove:main" in " ".join(proc.cmdline()):
            return proc
    raise RuntimeError("no bridge process")


def cpu_during(proc: psutil.Process, work) -> tuple[object, float]:
    """work()'s result, and proc's CPU meanwhile (% of one core)."""
    before, begin = proc.cpu_times(), time.monotonic()
    result = work()
    after, end = proc.cpu_times(), time.monotonic()
    used = (after.user + after.system) - (before.user + before.system)
    return result, 100.0 * used / (end - begin)


def rate_of(url: str, topic: str, kind: str, hz: float, env: dict[str, str],
            clients: int, seconds: float = 10.0) -> list[float]:
    publisher = subprocess.Popen([sys.executable, "-c", PUBLISHER, kind, topic, str(hz),
                                  str(seconds + 8)], env=env)
    try:
        time.sleep(3)
        procs = [client(url, {"do": "rate", "topic": topic, "seconds": seconds})
                 for _ in range(clients)]
        rates = []
        for proc in procs:
            lines = lines_of(proc)
            got = next((line for line in lines if "rate" in line), None)
            if got is None:
                raise RuntimeError(f"the client received nothing: {lines}")
            rates.append(got["count"] / got["seconds"])
        return rates
    finally:
        publisher.wait(30)


class ClockWatch:
    """The sim's /clock as this process receives it: (wall, sim) pairs."""

    def __init__(self) -> None:
        from launcher.bus.node import Node

        self.node = Node("bench_clock")
        self.samples: list[tuple[float, float]] = []

        def on_clock(payload: bytes) -> None:
            sec = int.from_bytes(payload[4:8], "little", signed=True)
            nanosec = int.from_bytes(payload[8:12], "little")
            self.samples.append((time.monotonic(), sec + nanosec * 1e-9))
        self.node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", on_clock, raw=True,
                                      inline=True)

    def rtf(self, seconds: float) -> float:
        begin = len(self.samples)
        time.sleep(seconds)
        (w0, s0), (w1, s1) = self.samples[begin], self.samples[-1]
        return (s1 - s0) / (w1 - w0)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=10.0)
    seconds = parser.parse_args().seconds
    env, router = start_router()
    env = {**env, "LAUNCHER_PACKAGE_PATH": str(REPO / "packages")}
    port = 18765
    bridge = subprocess.Popen([sys.executable, "-m", "launcher", "run", "foxglove_bridge",
                               "foxglove_bridge", "--ros-args", "-p", f"port:={port}"],
                              env=env, stderr=subprocess.PIPE, text=True)
    said: list[str] = []
    threading.Thread(target=lambda: said.extend(bridge.stderr), daemon=True).start()
    demo = None
    rows = []
    try:
        deadline = time.monotonic() + 60
        while not any("Foxglove connects to" in line for line in said):
            assert time.monotonic() < deadline, said
            time.sleep(0.1)
        url = re.search(r"Foxglove connects to (\S+)",
                        next(line for line in said if "Foxglove connects" in line)).group(1)
        process = bridge_process(bridge.pid)
        one, cpu = cpu_during(process, lambda: rate_of(url, "/bench_image", "image", 30, env, 1,
                                                       seconds))
        rows.append(("640x480 rgb8 at 30 Hz, one client: received, Hz", ">= 29",
                     f"{one[0]:.1f}"))  # type: ignore[index]
        rows.append(("  the bridge's CPU meanwhile, % of a core", "report", f"{cpu:.0f}"))
        three, cpu = cpu_during(process, lambda: rate_of(url, "/bench_image", "image", 30, env,
                                                         3, seconds))
        rows.append(("640x480 rgb8 at 30 Hz, three clients: each received, Hz", "report",
                     " ".join(f"{r:.1f}" for r in three)))  # type: ignore[union-attr]
        rows.append(("  the bridge's CPU meanwhile, % of a core", "report", f"{cpu:.0f}"))
        fast, cpu = cpu_during(process, lambda: rate_of(url, "/bench_small", "small", 1000,
                                                        env, 1, seconds))
        rows.append(("std_msgs/Int32 at 1 kHz, one client: received, Hz", ">= 990",
                     f"{fast[0]:.0f}"))  # type: ignore[index]
        rows.append(("  the bridge's CPU meanwhile, % of a core", "report", f"{cpu:.0f}"))
        demo = subprocess.Popen([sys.executable, "-m", "launcher", "launch",
                                 str(REPO / "launch_files" / "robot.launch.yaml")], env=env,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        watch = ClockWatch()
        deadline = time.monotonic() + 90
        while len(watch.samples) < 50:
            assert time.monotonic() < deadline, "the demo's clock did not come"
            time.sleep(0.2)
        time.sleep(5)  # (the robot spawned, driving)
        alone = watch.rtf(seconds)
        watcher = client(url, {"do": "watchall", "seconds": seconds + 4})
        time.sleep(2)
        watched = watch.rtf(seconds)
        got = next(line for line in lines_of(watcher) if "watched" in line)
        rows.append(("the demo's real-time factor, no client", "report", f"{alone:.3f}"))
        rows.append((f"  a client watching all {got['watched']} channels", ">= 0.97",
                     f"{watched:.3f} ({got['count']} messages)"))
        watch.node.destroy_node()
    finally:
        for proc in (demo, bridge, router):
            if proc is not None and proc.poll() is None:
                proc.send_signal(2)
                try:
                    proc.wait(30)
                except subprocess.TimeoutExpired:
                    proc.kill()
    table("viewing: the foxglove bridge to Foxglove's own client", rows)


if __name__ == "__main__":
    os.chdir(REPO)
    main()
