#!/usr/bin/env python3
"""Faults (issue 15): the sim under a `/cmd_vel` flood through the bridge (its real-time factor
and memory, against the same sim unflooded in the same run), and the time the whole demo takes
to be gone after SIGINT, SIGTERM or SIGKILL of the launcher (every process of it, counted by a
marker in their environment). Everything is real: the demo launch from the repo, its sim,
bridge and nodes, and a flooder publishing on the ROS side as fast as one process can."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
import uuid
from pathlib import Path

import psutil
from _harness import launcher_cmd, start_router, summary, table, workdir
from fault_campaign import campaign

REPO = Path(__file__).resolve().parent.parent

# Beside the demo, in its launch: reports the sim's real-time factor over each window.
PROBE = """
import json, sys, time
from launcher.bus import keys
from launcher.bus.node import Node
window = float(sys.argv[1])
node = Node("bench_probe")
odom, clocks = [], []
node.create_subscription("nav_msgs/msg/Odometry", "/odom", odom.append)
node.create_subscription("mujoco_sim/msg/Clock", "/world/robot/clock",
                         lambda c: clocks.append((time.monotonic(),
                                                  c.sim.sec + c.sim.nanosec * 1e-9)),
                         space=keys.SIM)
while not odom:
    node.spin_once(0.05)
print("PROBE " + json.dumps({"odom": time.time()}), flush=True)
while not node.interrupted:  # Ctrl-C (the launch's SIGINT) ends the spin and the probe
    clocks.clear()
    node.spin(window)
    if len(clocks) > 1:
        (w0, s0), (w1, s1) = clocks[0], clocks[-1]
        print("PROBE " + json.dumps({"rtf": (s1 - s0) / (w1 - w0)}), flush=True)
"""

FLOODER = """
import sys, time
from launcher.bus.node import Node
node = Node("bench_flooder")
publisher = node.create_publisher("geometry_msgs/msg/Twist", "/cmd_vel")
message = node.message("geometry_msgs/msg/Twist", linear={"x": 0.3}, angular={"z": 0.2})
from launcher.bus.types import registry
payload = registry().serialize(message, "geometry_msgs/msg/Twist")
time.sleep(1.0)
end, sent = time.monotonic() + float(sys.argv[1]), 0
while time.monotonic() < end:
    for _ in range(100):
        publisher.publish_raw(payload)
    sent += 100
print(f"FLOOD {sent / float(sys.argv[1]):.0f}", flush=True)
node.destroy_node()
"""


def tagged(tag: str) -> list[psutil.Process]:
    found = []
    for proc in psutil.process_iter(["pid"]):
        try:
            if proc.environ().get("BENCH_FAULT_TAG") == tag and \
                    proc.status() != psutil.STATUS_ZOMBIE:
                found.append(proc)
        except psutil.Error:
            continue
    return found


def start_demo(root: Path, env: dict[str, str], window: float) -> tuple[subprocess.Popen, list]:
    """The demo (not driving: the flood is the only command) with the probe; its PROBE lines
    arrive on the returned list."""
    (root / "probe.py").write_text(PROBE)
    wrapper = root / "bench.launch.yaml"
    wrapper.write_text(f"""
launch:
  - include:
      file: {REPO / 'launch_files' / 'robot.launch.yaml'}
      arg: [{{name: drive, value: 'false'}}]
  - executable:
      cmd: {sys.executable} {root / 'probe.py'} {window}
      name: bench_probe
      output: screen
""")
    proc = subprocess.Popen([*launcher_cmd(), "launch", str(wrapper), "--noninteractive"],
                            cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, env=env)
    reports: list = []

    def read() -> None:
        for line in proc.stdout:
            if "PROBE " in line:
                reports.append(json.loads(line.split("PROBE ", 1)[1]))

    threading.Thread(target=read, daemon=True).start()
    return proc, reports


def wait_report(reports: list, key: str, after: int = 0, timeout: float = 120.0) -> dict:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        for report in reports[after:]:
            if key in report:
                return report
        time.sleep(0.05)
    raise TimeoutError(f"no {key} report in {timeout} s")


def sim_process(launcher: int) -> psutil.Process:
    for proc in psutil.Process(launcher).children(recursive=True):
        try:
            words = proc.cmdline()
            if "sim" in words and ("gz" in words or any("launcher" in w for w in words)):
                return proc  # `gz sim …` (the launch file's) or `launcher sim …`
        except psutil.Error:
            continue
    raise RuntimeError("no sim process in the launch")


def flood(root: Path, env: dict[str, str]) -> list[tuple[str, str, str]]:
    tag = uuid.uuid4().hex
    env = {**env, "BENCH_FAULT_TAG": tag}
    window = 2.0
    proc, reports = start_demo(root, env, window)
    try:
        wait_report(reports, "odom")
        sim = sim_process(proc.pid)
        calm = [wait_report(reports, "rtf", len(reports))["rtf"] for _ in range(3)]
        rss_before = sim.memory_info().rss
        (root / "flooder.py").write_text(FLOODER)
        duration = 12.0
        flooder = subprocess.Popen([sys.executable, str(root / "flooder.py"), str(duration)],
                                   env=env, stdout=subprocess.PIPE, text=True)
        time.sleep(1.5)  # the flood under way
        flooded, peak = [], rss_before
        end = time.monotonic() + duration - 2.0
        while time.monotonic() < end:
            mark = len(reports)
            flooded.append(wait_report(reports, "rtf", mark)["rtf"])
            peak = max(peak, sim.memory_info().rss)
        out, _ = flooder.communicate(60)
        rate = out.split("FLOOD ", 1)[1].strip() if "FLOOD " in out else "?"
    finally:
        proc.send_signal(signal.SIGINT)
        proc.wait(60)
    return [
        ("flood: /cmd_vel messages published per second", "report", rate),
        ("sim RTF, no flood (2 s windows)", "report", summary(calm)),
        ("sim RTF under the flood (2 s windows)", ">= 0.95", summary(flooded)),
        ("sim RTF under the flood, worst 2 s window", "report", f"{min(flooded):.3f}"),
        ("sim RSS growth during the flood, MiB", "report",
         f"{(peak - rss_before) / 2**20:.1f}"),
    ]


def stop_times(root: Path, env: dict[str, str], runs: int) -> list[tuple[str, str, str]]:
    rows = []
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGKILL):
        times = []
        for _ in range(runs):
            tag = uuid.uuid4().hex
            proc, reports = start_demo(root, {**env, "BENCH_FAULT_TAG": tag}, 2.0)
            wait_report(reports, "odom")
            time.sleep(1.0)
            sent = time.monotonic()
            proc.send_signal(sig)
            while tagged(tag) and time.monotonic() - sent < 60:
                time.sleep(0.02)
            times.append(time.monotonic() - sent)
            proc.wait(60)
        limit = "<= 5.0" if sig != signal.SIGKILL else "<= 1.5"
        rows.append((f"demo: {sig.name} -> every process gone, s", limit, summary(times)))
    return rows


def stop_after_sim_killed(root: Path, env: dict[str, str], runs: int) -> list[tuple[str, str, str]]:
    """Ctrl-C of the demo whose sim was SIGKILLed a moment before: the launch has nothing of
    the sim's to wait for, so it ends as fast as with the sim alive."""
    times = []
    for _ in range(runs):
        tag = uuid.uuid4().hex
        proc, reports = start_demo(root, {**env, "BENCH_FAULT_TAG": tag}, 2.0)
        wait_report(reports, "odom")
        sim_process(proc.pid).kill()
        time.sleep(1.0)
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)
        while tagged(tag) and time.monotonic() - sent < 60:
            time.sleep(0.02)
        times.append(time.monotonic() - sent)
        proc.wait(60)
    return [("demo, sim SIGKILLed: SIGINT -> every process gone, s", "<= 1.0", summary(times))]


def main() -> None:
    root = workdir()
    env, router = start_router()  # standing: no launch's marker on it
    runs = int(os.environ.get("BENCH_FAULT_RUNS", "3"))
    try:
        rows = flood(root, env) + stop_times(root, env, runs) + \
            stop_after_sim_killed(root, env, runs)
    finally:
        router.send_signal(signal.SIGINT)
        router.wait(30)
    table("faults (bench/faults.py)", rows)
    runs = int(os.environ.get("BENCH_FAULT_CAMPAIGN", "1000"))  # (bench/fault_campaign.py)
    table(f"The fault campaign: {runs} runs", campaign(runs, 56, []))


if __name__ == "__main__":
    main()
