"""Shared helpers for the benchmarks: temporary launch files, child polling, tables."""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path


def launcher_cmd() -> list[str]:
    exe = Path(sys.executable).with_name("launcher")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "launcher"]


def workdir() -> Path:
    path = Path(tempfile.mkdtemp(prefix="launcher-bench-"))
    os.environ["LAUNCHER_LOG_DIR"] = str(path / "log")
    return path


def children(pid: int) -> list[int]:
    """Direct children of pid, read from /proc (cheap enough to poll every millisecond)."""
    out: list[int] = []
    try:
        for tid in os.listdir(f"/proc/{pid}/task"):
            with open(f"/proc/{pid}/task/{tid}/children") as handle:
                out += [int(p) for p in handle.read().split()]
    except OSError:
        pass
    return out


def comm(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/comm") as handle:
            return handle.read().strip()
    except OSError:
        return ""


def wait_for(predicate: Callable[[], bool], timeout: float = 30.0, step: float = 0.0005) -> float:
    start = time.perf_counter()
    while not predicate():
        if time.perf_counter() - start > timeout:
            raise TimeoutError("condition not reached")
        time.sleep(step)
    return time.perf_counter()


def start(args: list[str], **kwargs) -> subprocess.Popen:
    return subprocess.Popen(launcher_cmd() + args, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, **kwargs)


def stop(proc: subprocess.Popen, wait: float = 10.0) -> None:
    """Ctrl-C, and SIGKILL after `wait` seconds."""
    if proc.poll() is None:
        proc.send_signal(2)
        try:
            proc.wait(wait)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def start_router() -> tuple[dict[str, str], subprocess.Popen]:
    """A graph of the benchmark's own (a run folder of its own, with a standing router), and
    the environment that puts child processes (and this process) on it."""
    from launcher.bus import discovery

    run = tempfile.mkdtemp(prefix="launcher-bench-")
    env = {**os.environ, "LAUNCHER_RUN_DIR": run}
    env.pop(discovery.ROUTER_VARIABLE, None)
    os.environ.update({"LAUNCHER_RUN_DIR": run})
    os.environ.pop(discovery.ROUTER_VARIABLE, None)
    router = subprocess.Popen([sys.executable, "-m", "launcher.bus.router"], env=env,
                              stdout=subprocess.DEVNULL)
    deadline = time.monotonic() + 10
    while not discovery.answers(discovery.socket_path(env)) and time.monotonic() < deadline:
        time.sleep(0.05)
    return env, router


def summary(values: list[float]) -> str:
    values = sorted(values)
    return (f"median {statistics.median(values):.3f}  min {values[0]:.3f}  "
            f"max {values[-1]:.3f}  (n={len(values)})")


def table(title: str, rows: list[tuple[str, str, str]]) -> None:
    """Print the rows; under bench/run_all also hand them on for its one table at the end."""
    if os.environ.get("BENCH_ROWS"):
        with open(os.environ["BENCH_ROWS"], "a") as handle:
            for row in rows:
                handle.write(json.dumps([Path(sys.argv[0]).name, *row]) + "\n")
    width = max(len(r[0]) for r in rows)
    print(f"\n{title}")
    print(f"  {'benchmark'.ljust(width)}  {'target':<14}  result")
    for name, target, result in rows:
        print(f"  {name.ljust(width)}  {target:<14}  {result}")
