#!/usr/bin/env python3
"""Logs under a flood (issue 56): two processes writing as fast as they can, one to stdout
(shown on the screen) and one to stderr, for `--seconds` (60 in the issue's figure). Measured
from outside, in the same run, for launcher and for real ros2 launch (installed apart, as the
fidelity oracle installs it: `--ros2 DIR`, default .fidelity/ros2):

- the launcher's peak resident memory (sampled every 0.1 s);
- the bytes the flooders produced, and the flood's lines the log files hold against the lines
  produced (launcher: `launch.log*`, which holds both streams; whole, or lines were lost);
- the screen: lines shown, lines the launch said it did not show, and the lag from a line's
  writing to its reaching the screen (p50, p99, max).

Each flooder's lines carry their sequence number and the time they were written.

    python bench/logs.py [--seconds 20] [--ros2 DIR]
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import psutil
from _harness import launcher_cmd, table

REPO = Path(__file__).resolve().parent.parent
FLOODER = """
import os, sys, time
fd, seconds, count_file = int(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
pad = "x" * 60
end = time.monotonic() + seconds
sent = lines = 0
seq = 0
while time.monotonic() < end:
    stamp = f"{time.time():.6f}"
    block = "".join(f"{stamp} {seq + i:012d} {pad}\\n" for i in range(512)).encode()
    seq += 512
    view = memoryview(block)
    while view:
        written = os.write(fd, view)
        view = view[written:]
    sent += len(block)
    lines += 512
with open(count_file, "w") as out:
    out.write(f"{sent} {lines}")
"""
LINE = re.compile(rb"(\d+\.\d{6}) (\d{12}) x")
ROS2_FILE = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=[{py!r}, {flooder!r}, "1", "{seconds}", {out_count!r}],
                       output="both", name="flood_out"),
        ExecuteProcess(cmd=[{py!r}, {flooder!r}, "2", "{seconds}", {err_count!r}],
                       output="log", name="flood_err"),
    ])
"""
LAUNCHER_FILE = """
launch:
  - executable: {{cmd: "{py} {flooder} 1 {seconds} {out_count}", output: both,
                 name: flood_out}}
  - executable: {{cmd: "{py} {flooder} 2 {seconds} {err_count}", name: flood_err}}
"""


class Screen:
    """Reads a launch's stdout as a fast terminal would; notes each flood line's lag."""

    def __init__(self, stream) -> None:
        self.stream, self.lags, self.lines, self.said_dropped = stream, [], 0, 0
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self) -> None:
        pending = b""
        while chunk := self.stream.read1(1 << 20):
            now = time.time()
            pending += chunk
            *whole, pending = pending.split(b"\n")
            for line in whole:
                found = LINE.search(line)
                if found:
                    self.lines += 1
                    if self.lines % 64 == 0:
                        self.lags.append(now - float(found.group(1)))
                elif b"lines were not shown" in line:
                    self.said_dropped += int(line.split()[1])


def peak_rss(pid: int, done: threading.Event, peaks: list[int]) -> None:
    try:
        proc = psutil.Process(pid)
        while not done.is_set():
            peaks.append(proc.memory_info().rss)
            time.sleep(0.1)
    except psutil.Error:
        pass


def count_lines(paths: list[Path]) -> int:
    """The flooders' lines the files hold (their own messages aside)."""
    total = 0
    for path in paths:
        with open(path, "rb") as handle:
            rest = b""
            while block := handle.read(1 << 24):
                block = rest + block
                cut = block.rfind(b"\n") + 1
                total += len(LINE.findall(block, 0, cut))
                rest = block[cut:]
    return total


def run(name: str, argv: list[str], env: dict[str, str], folder: Path, seconds: float,
        logs: callable) -> dict:
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env,
                            cwd=folder)
    screen = Screen(proc.stdout)
    done, peaks = threading.Event(), []
    sampler = threading.Thread(target=peak_rss, args=(proc.pid, done, peaks), daemon=True)
    sampler.start()
    try:
        proc.wait(seconds + 120)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
    done.set()
    screen.thread.join(30)
    produced = lines = 0
    for stream in ("out", "err"):
        sent, count = (folder / f"{name}-{stream}.count").read_text().split()
        produced += int(sent)
        lines += int(count)
    logged = logs()
    lags = sorted(screen.lags) or [0.0]
    return {"rss": max(peaks, default=0) / 1e6, "produced": produced, "lines": lines,
            "logged": logged, "shown": screen.lines, "said": screen.said_dropped,
            "lag50": statistics.median(lags), "lag99": lags[int(len(lags) * 0.99)],
            "lagmax": lags[-1]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--ros2", type=Path, default=REPO / ".fidelity" / "ros2")
    parser.add_argument("--only", choices=("launcher", "ros2"), default=None,
                        help="measure one of the two")
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-logs-"))
    flooder = folder / "flooder.py"
    flooder.write_text(FLOODER)
    env = {**os.environ, "LAUNCHER_LOG_DIR": str(folder / "log"),
           "LAUNCHER_RUN_DIR": str(folder / "run"), "ROS_LOG_DIR": str(folder / "roslog")}
    results = {}
    try:
        form = {"py": sys.executable, "flooder": flooder, "seconds": args.seconds}
        (folder / "flood.launch.yaml").write_text(LAUNCHER_FILE.format(
            **form, out_count=folder / "launcher-out.count",
            err_count=folder / "launcher-err.count"))
        if args.only != "ros2":
            results["launcher"] = run(
                "launcher", [*launcher_cmd(), "launch", "-n", "--log-max-size", "1TiB",
                             "flood.launch.yaml"], env, folder, args.seconds,
                lambda: count_lines(sorted((folder / "log").glob("*-*/launch.log*"))))
        shutil.rmtree(folder / "log", ignore_errors=True)
        python = args.ros2 / "bin" / "python"
        if python.exists() and args.only != "launcher":
            (folder / "flood.launch.py").write_text(ROS2_FILE.format(
                **{**form, "flooder": str(flooder)}, out_count=str(folder / "ros2-out.count"),
                err_count=str(folder / "ros2-err.count")))
            results["ros2 launch"] = run(
                "ros2", [str(python), str(args.ros2 / "drive.py"),
                         str(folder / "flood.launch.py")], env, folder, args.seconds,
                lambda: count_lines(sorted((folder / "roslog").rglob("*.log"))))
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    rows = []
    for who, r in results.items():
        rate = r["produced"] / args.seconds / 1e6
        rows += [
            (f"{who}: peak RSS (MB)", "≤ 150" if who == "launcher" else "-", f"{r['rss']:.0f}"),
            (f"{who}: produced (MB/s, both streams)", "-", f"{rate:.0f}"),
            (f"{who}: log lines / lines produced", "1.000",
             f"{r['logged'] / max(r['lines'], 1):.3f} ({r['logged']} of {r['lines']})"),
            (f"{who}: screen lines shown / said not shown", "-", f"{r['shown']} / {r['said']}"),
            (f"{who}: screen lag p50 / p99 / max (s)", "-",
             f"{r['lag50']:.3f} / {r['lag99']:.3f} / {r['lagmax']:.3f}"),
        ]
    if "ros2 launch" in results and "launcher" in results:
        rows.append(("peak RSS, launcher / ros2 launch", "-",
                     f"{results['launcher']['rss'] / max(results['ros2 launch']['rss'], 1):.2f}"))
    elif "ros2 launch" not in results:
        rows.append(("ros2 launch", "-", f"not installed at {args.ros2}: no anchor this run"))
    table(f"Logs under a flood: two flooders for {args.seconds:g} s, stdout on the screen "
          "and in the log", rows)


if __name__ == "__main__":
    main()
