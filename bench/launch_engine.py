"""Launch engine benchmarks (issue 2): start-up, exit, scale, --show-args, Ctrl-C.

Each figure is the median of several runs, measured from outside as a user would see it:
wall time from starting `launcher launch` until the condition holds. 10 and 100 `true`
processes to the launch's exit are also run by real ros2 launch (installed apart as the
fidelity oracle is: `--ros2 DIR`, default .fidelity/ros2), the same YAML file, in the same
run, the two taken in turn; the ratio is printed (issue 57: ≤ 0.15×).
"""

from __future__ import annotations

import argparse
import contextlib
import signal
import statistics
import subprocess
import sys
import time
from pathlib import Path

import psutil
from _harness import children, comm, launcher_cmd, start, stop, summary, table, wait_for, workdir

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))  # (real ros2 launch, run as the fidelity oracle runs it)
from tests.fidelity.record import ros2_tool  # noqa: E402


def sleeps_file(folder, count: int, seconds: int = 5) -> str:
    body = "".join(f"  - executable: {{cmd: sleep {seconds}, output: screen}}\n"
                   for _ in range(count))
    path = folder / f"sleep{count}.launch.yaml"
    path.write_text("launch:\n" + body)
    return str(path)


def time_to_running(path: str, count: int) -> tuple[float, float]:
    t0 = time.perf_counter()
    proc = start(["launch", path])
    peak = 0
    try:
        def all_running() -> bool:
            return sum(comm(c) == "sleep" for c in children(proc.pid)) >= count
        t1 = wait_for(all_running)
        with contextlib.suppress(psutil.Error):
            peak = psutil.Process(proc.pid).memory_info().rss
        return t1 - t0, peak / 1e6
    finally:
        stop(proc)


def time_to_exit(path: str, argv: list[str] | None = None,
                 env: dict[str, str] | None = None) -> float:
    """Seconds from the start of `argv PATH` (launcher launch's by default) to its exit."""
    t0 = time.perf_counter()
    subprocess.run([*(argv or [*launcher_cmd(), "launch"]), path], stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, check=True, env=env)
    return time.perf_counter() - t0


def against_ros2(folder: Path, ros2: Path, runs: int) -> list[tuple[str, str, str]]:
    """10 and 100 `true` to the exit, launcher and real ros2 launch in turn: the rows."""
    real = ros2_tool(ros2)
    rows = []
    for count in (10, 100):
        path = folder / f"true{count}.launch.yaml"
        path.write_text("launch:\n" + "  - executable: {cmd: 'true'}\n" * count)
        ours, theirs = [], []
        time_to_exit(str(path))  # (the file cache warm, both ways)
        time_to_exit(str(path), list(real.command), real.env)
        for _ in range(runs):
            ours.append(time_to_exit(str(path)))
            theirs.append(time_to_exit(str(path), list(real.command), real.env))
        ratio = statistics.median(ours) / statistics.median(theirs)
        rows += [(f"{count} x true: launcher exited", "report", summary(ours)),
                 (f"{count} x true: ros2 launch exited", "report", summary(theirs)),
                 (f"{count} x true: launcher / ros2 launch (medians)", "<= 0.15",
                  f"{ratio:.2f}")]
    return rows


def time_ctrl_c(path: str, count: int) -> float:
    proc = start(["launch", path])
    wait_for(lambda: sum(comm(c) == "sleep" for c in children(proc.pid)) >= count)
    pids = [c for c in children(proc.pid) if comm(c) == "sleep"]
    t0 = time.perf_counter()
    proc.send_signal(signal.SIGINT)
    wait_for(lambda: not any(alive(p) for p in pids))
    t1 = time.perf_counter()
    proc.wait(10)
    return t1 - t0


def alive(pid: int) -> bool:
    """Running (a zombie waiting to be reaped has finished)."""
    try:
        with open(f"/proc/{pid}/stat") as handle:
            return handle.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def include_tree(folder) -> str:
    leaf = folder / "leaf.launch.yaml"
    leaf.write_text("launch:\n  - arg: {name: leaf_arg, default: '1', description: a leaf}\n")
    mid = folder / "mid.launch.xml"
    mid.write_text('<launch><arg name="mid_arg" default="2"/>'
                   '<include file="$(dirname)/leaf.launch.yaml"/></launch>')
    top = folder / "top.launch.yaml"
    top.write_text("launch:\n  - arg: {name: top_arg, default: '3'}\n"
                   "  - include: {file: $(dirname)/mid.launch.xml}\n")
    return str(top)


def time_show_args(path: str) -> float:
    t0 = time.perf_counter()
    out = subprocess.run(launcher_cmd() + ["launch", path, "--show-args"],
                         capture_output=True, text=True, check=True).stdout
    assert "leaf_arg" in out, out
    return time.perf_counter() - t0


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--ros2", type=Path, default=REPO / ".fidelity" / "ros2")
    parser.add_argument("--only-ros2", action="store_true",
                        help="only the figures against ros2 launch")
    args = parser.parse_args()
    runs = args.runs
    folder = workdir()
    if (args.ros2 / "bin" / "python").exists():
        table("launch engine against ros2 launch (seconds)", against_ros2(folder, args.ros2,
                                                                        runs))
    else:
        print(f"ros2 launch: not installed at {args.ros2}: no anchor this run")
    if args.only_ros2:
        return
    ten, hundred, fifty = (sleeps_file(folder, n) for n in (10, 100, 50))
    trues = folder / "true10.launch.yaml"
    trues.write_text("launch:\n" + "  - executable: {cmd: 'true'}\n" * 10)
    tree = include_tree(folder)
    time_to_exit(str(trues))  # warm the file cache

    r10 = [time_to_running(ten, 10)[0] for _ in range(runs)]
    rtrue = [time_to_exit(str(trues)) for _ in range(runs)]
    r100 = [time_to_running(hundred, 100) for _ in range(max(3, runs // 2))]
    rshow = [time_show_args(tree) for _ in range(runs)]
    rint = [time_ctrl_c(fifty, 50) for _ in range(max(3, runs // 2))]
    table("launch engine (seconds; RSS in MB)", [
        ("10 x sleep 5: all running", "<= 0.10", summary(r10)),
        ("10 x true: launcher exited", "<= 0.15", summary(rtrue)),
        ("100 x sleep 5: all running", "<= 0.6", summary([r[0] for r in r100])),
        ("100 x sleep 5: launcher RSS", "<= 60 MB", summary([r[1] for r in r100])),
        ("--show-args, 3-level includes", "<= 0.10", summary(rshow)),
        ("Ctrl-C, 50 children: all gone", "<= 0.5", summary(rint)),
    ])


if __name__ == "__main__":
    main()
