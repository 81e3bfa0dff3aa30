#!/usr/bin/env python3
"""The demo end to end (issue 7): `launcher launch launch_files/robot.launch.yaml` to the first
/odom on the ROS side; 5, 10 and 50 robots from multi_robot.launch.yaml (time until all
publish odometry, the sim's real-time factor while they all drive at 1 kHz physics); the whole
demo's memory; 50 robots' Ctrl-C (SIGINT to the end of the launch, and how many of its
processes needed SIGTERM or SIGKILL), started in the foreground and as a script's background
job starts it (SIGINT and SIGQUIT ignored). Everything is real: the launches run from the
repo as a user runs them, and a probe node inside each launch reports what it hears."""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import psutil
from _harness import launcher_cmd, summary, table, workdir

REPO = Path(__file__).resolve().parent.parent

# A node started by the same launch: prints a JSON line when each topic's first message
# arrives (wall time), then the sim's real-time factor over a window once all have arrived
# (from one clock message at each end of the window).
PROBE = """
import json, sys, time
from launcher.bus import keys
from launcher.bus.node import Node
topics, window = sys.argv[1].split(","), float(sys.argv[2])
node = Node("bench_probe")
first = {}
def heard(topic):
    def first_message(message):
        if topic not in first:
            first[topic] = time.time()
            print("PROBE " + json.dumps({"first": {topic: first[topic]}}), flush=True)
    return first_message
subscriptions = [node.create_subscription("nav_msgs/msg/Odometry", topic, heard(topic))
                 for topic in topics]
def clock_now():
    # (wall, sim) time from one clock message: subscribed only for it, so the sim does not
    # publish its 1 kHz clock for the probe's sake the rest of the time
    got = []
    sub = node.create_subscription("mujoco_sim/msg/Clock", "/world/robot/clock",
                                   lambda c: got.append((time.monotonic(),
                                                         c.sim.sec + c.sim.nanosec * 1e-9)),
                                   space=keys.SIM)
    while not got:
        node.spin_once(0.05)
    sub.destroy()
    return got[0]
while len(first) < len(topics):
    node.spin_once(0.05)
print("PROBE " + json.dumps({"all": True}), flush=True)
for subscription in subscriptions:  # heard: no load of the probe's from here on
    subscription.destroy()
node.spin(2.0)  # let start-up settle
w0, s0 = clock_now()
node.spin(window)
w1, s1 = clock_now()
print("PROBE " + json.dumps({"rtf": (s1 - s0) / (w1 - w0)}), flush=True)
node.spin(1000)
"""


def as_a_script_job() -> None:
    """What a non-interactive shell does to a job it starts with `&`."""
    for sig in (signal.SIGINT, signal.SIGQUIT):
        signal.signal(sig, signal.SIG_IGN)


def run(root: Path, launch: str, args: list[str], topics: list[str], window: float,
        timeout: float = 180.0, script: bool = False) -> dict:
    """Start `launch` with a probe beside it; its reports, plus the tree's memory, and how
    long its SIGINT took to end it ("stop", s) and how many processes were escalated."""
    (root / "probe.py").write_text(PROBE)
    wrapper = root / "bench.launch.yaml"
    arg_lines = "".join(f"\n        - {{name: {a.split(':=')[0]}, value: '{a.split(':=')[1]}'}}"
                        for a in args)
    wrapper.write_text(f"""
launch:
  - include:
      file: {REPO / 'launch_files' / launch}
      arg:{arg_lines or ' []'}
  - executable:
      cmd: {sys.executable} {root / 'probe.py'} {','.join(topics)} {window}
      name: bench_probe
      output: screen
""")
    started = time.time()
    proc = subprocess.Popen([*launcher_cmd(), "launch", str(wrapper), "--noninteractive"],
                            cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, preexec_fn=as_a_script_job if script else None)
    result: dict = {"started": started, "first": {}}
    timer = threading.Timer(timeout, proc.send_signal, (2,))  # gives up: partial figures
    timer.start()
    try:
        for line in proc.stdout:
            if "PROBE " in line:
                report = json.loads(line.split("PROBE ", 1)[1])
                result["first"].update(report.pop("first", {}))
                result.update(report)
                if "rtf" in result:
                    break
                if "all" in report:
                    result["rss"], result["uss"] = memory(proc.pid)
    finally:
        timer.cancel()
        signalled = time.monotonic()
        proc.send_signal(signal.SIGINT)
        rest = proc.stdout.read()  # to its end: the launcher has exited
        result["stop"] = time.monotonic() - signalled
        result["escalated"] = rest.count("still running; sending")
        proc.wait(60)
    return result


def memory(pid: int) -> tuple[float, float]:
    """Sum of RSS and of USS (pages no other process shares) over the launch's processes, the
    probe left out, in MiB."""
    root = psutil.Process(pid)
    rss = uss = 0
    for proc in [root, *root.children(recursive=True)]:
        try:
            if "probe.py" in " ".join(proc.cmdline()):
                continue
            info = proc.memory_full_info()
        except psutil.Error:
            continue
        rss, uss = rss + info.rss, uss + info.uss
    return rss / 2**20, uss / 2**20


def main() -> None:
    root = workdir()
    firsts, rss, uss, rtf1 = [], [], [], []
    for _ in range(3):
        result = run(root, "robot.launch.yaml", ["drive:=false"], ["/odom"], 5.0)
        firsts.append(result["first"]["/odom"] - result["started"])
        rss.append(result["rss"])
        uss.append(result["uss"])
        rtf1.append(result["rtf"])
    rows = [
        ("launch -> first /odom (ROS side), s", "<= 2.0", summary(firsts)),
        ("1 robot: sim RTF at 1 kHz", "report", summary(rtf1)),
        ("1 robot demo: sum of RSS, MiB", "report", summary(rss)),
        ("1 robot demo: sum of USS, MiB", "report", summary(uss)),
    ]
    for count in (5, 10, 50):
        topics = [f"/robot_{i}/odom" for i in range(count)]
        many = run(root, "multi_robot.launch.yaml", [f"count:={count}"], topics, 10.0, 120.0)
        heard = len(many["first"])
        if heard < count:
            rows.append((f"{count} robots: launch -> all odometry, s", "report",
                         f"not reached: {heard} of {count} in 120 s"))
            continue
        firsts = sorted(many["first"].values())
        all_odom = firsts[-1] - many["started"]
        gaps = [b - a for a, b in zip(firsts[:-1], firsts[1:], strict=True)]
        rows += [
            (f"{count} robots: launch -> all odometry, s", "<= 3.0" if count == 50 else
             "report", f"{all_odom:.3f}"),
            (f"{count} robots: gap between first odometries, last ten (mean), s", "report",
             f"{sum(gaps[-10:]) / max(len(gaps[-10:]), 1):.3f}"),
            (f"{count} robots driving: sim RTF at 1 kHz", ">= 1.0", f"{many['rtf']:.3f}"),
            (f"{count} robots: sum of RSS, MiB", "report", f"{many['rss']:.0f}"),
            (f"{count} robots: sum of USS, MiB", "report", f"{many['uss']:.0f}"),
        ]
        if count == 50:
            script = run(root, "multi_robot.launch.yaml", [f"count:={count}"], topics, 1.0,
                         120.0, script=True)
            for how, result in (("foreground", many), ("started by a script", script)):
                rows += [(f"{count} robots, {how}: SIGINT -> launch ended, s", "<= 1.0",
                          f"{result['stop']:.3f}"),
                         (f"{count} robots, {how}: processes sent SIGTERM or SIGKILL", "0",
                          str(result["escalated"]))]
    table("demo (bench/demo.py)", rows)


if __name__ == "__main__":
    main()
