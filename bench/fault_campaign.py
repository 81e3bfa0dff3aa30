#!/usr/bin/env python3
"""The fault campaign (issue 56; bench/faults.py runs it after its own figures): runs of a real
launch, each hit by one fault, each checked for what it left running, for a hang, and for its
exit status against the documented ones (0, 1, 130 after SIGINT, 143 after SIGTERM; -9 when
the launcher itself was SIGKILLed).

Launches (each run picks one):
- children: 1-12 processes of the kinds that try to escape or resist (a sleeper, a `setsid`
  grandchild, `set -m` job control, a double-forking daemon, one that ignores SIGINT, one
  that ignores SIGINT and SIGTERM, a crash, a failure, a respawn storm);
- demo: the repo's robot.launch.yaml (sim, bridge, robot_state_publisher, create);
- lockstep: the repo's robot_lockstep.launch.yaml;
- foxglove: the Foxglove bridge node beside a sleeper;
- launch test: `launcher test` of a launch_testing file whose process it checks.

Faults: SIGINT, SIGTERM or SIGKILL of the launcher at a random moment of its first seconds;
Ctrl-C twice and three times; SIGKILL of a random child or grandchild, then Ctrl-C; the log
folder on a full 256 KiB tmpfs (root only: else said and not run); a full file-descriptor
table (`prlimit --nofile`); the sim under memory pressure (`prlimit --as` as its prefix).

    python bench/fault_campaign.py [--runs 1000] [--seed 56]
"""

from __future__ import annotations

import argparse
import contextlib
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import uuid
from collections import Counter
from pathlib import Path

import psutil
from _harness import launcher_cmd, table

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))  # (the children that resist, shared with the custody tests)
from tests.support.resisting import DAEMON, STUBBORN, children_launch  # noqa: E402

TAG = "BENCH_CAMPAIGN_TAG"
HANG = 60.0  # seconds after its fault a launcher may take to exit
SETTLE = 10.0  # seconds its watchdog may take to end what a SIGKILLed launcher left

LAUNCH_TEST = """
import unittest
import launch
import launch_testing.actions
from launch.actions import ExecuteProcess


def generate_test_description():
    sleeper = ExecuteProcess(cmd=["sleep", "30"], name="sleeper")
    return launch.LaunchDescription([sleeper, launch_testing.actions.ReadyToTest()]), \\
        {"sleeper": sleeper}


class TestRuns(unittest.TestCase):
    def test_it_runs(self, proc_info, sleeper):
        import time
        time.sleep(20)
"""
LAUNCHES = ("children", "demo", "lockstep", "foxglove", "launch test")
FAULTS = ("SIGINT", "SIGTERM", "SIGKILL", "Ctrl-C twice", "Ctrl-C three times",
          "kill a child", "kill a grandchild", "full disk", "full fd table",
          "memory pressure")


def command(kind: str, folder: Path, rng: random.Random, prefix: str) -> list[str]:
    """The launcher's command line for a launch of `kind`."""
    if kind == "children":
        (folder / "c.launch.yaml").write_text(children_launch(rng, most=12, timeout=0.5))
        return [*launcher_cmd(), "launch", "-n", "c.launch.yaml"]
    if kind in ("demo", "lockstep"):
        name = "robot.launch.yaml" if kind == "demo" else "robot_lockstep.launch.yaml"
        extra = [f"--launch-prefix={prefix}"] if prefix else []
        return [*launcher_cmd(), "launch", "-n", *extra, str(REPO / "launch_files" / name),
                "drive:=false"]
    if kind == "foxglove":
        (folder / "f.launch.yaml").write_text(
            "launch:\n  - node: {pkg: foxglove_bridge, exec: foxglove_bridge, "
            "param: [{name: port, value: 0}]}\n  - executable: {cmd: sleep 120}\n")
        return [*launcher_cmd(), "launch", "-n", "f.launch.yaml"]
    (folder / "test_runs.py").write_text(LAUNCH_TEST)
    return [*launcher_cmd(), "test", "test_runs.py"]


def carrying(tag: str) -> list[psutil.Process]:
    found = []
    for proc in psutil.process_iter():
        try:
            if proc.environ().get(TAG) != tag or proc.status() == psutil.STATUS_ZOMBIE:
                continue
            if "launcher.bus.router" in " ".join(proc.cmdline()):
                continue  # (the graph's: detached on purpose, it outlives launches)
            found.append(proc)
        except psutil.Error:
            continue
    return found


def descendants(pid: int) -> list[psutil.Process]:
    try:
        return psutil.Process(pid).children(recursive=True)
    except psutil.Error:
        return []


def parent(proc: psutil.Process) -> int:
    """Its parent's pid; -1 once it is gone."""
    try:
        return proc.ppid()
    except psutil.Error:
        return -1


@contextlib.contextmanager
def small_disk(folder: Path):
    """A 256 KiB tmpfs, filled up, as the log folder's disk."""
    mount = folder / "disk"
    mount.mkdir()
    subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(mount)], check=True)
    try:
        with contextlib.suppress(OSError), open(mount / "filler", "wb") as filler:
            while True:
                filler.write(b"\0" * 4096)
                filler.flush()
        yield mount
    finally:
        subprocess.run(["umount", "-l", str(mount)], check=False)


def one(kind: str, fault: str, rng: random.Random, base: Path,
        env: dict[str, str]) -> tuple[str, int, str]:
    """(outcome, processes left, details) of one run."""
    folder = Path(tempfile.mkdtemp(dir=base))
    (folder / "daemon.py").write_text(DAEMON)
    (folder / "stubborn.py").write_text(STUBBORN)
    tag = uuid.uuid4().hex
    run_env = {**env, TAG: tag, "LAUNCHER_LOG_DIR": str(folder / "log")}
    prefix = "prlimit --as=400000000" if fault == "memory pressure" else ""
    argv = command(kind, folder, rng, prefix)
    if fault == "full fd table":
        argv = ["prlimit", "--nofile=40", *argv]
    with contextlib.ExitStack() as stack:
        if fault == "full disk":
            run_env["LAUNCHER_LOG_DIR"] = str(stack.enter_context(small_disk(folder)) / "log")
        proc = subprocess.Popen(argv, cwd=folder, env=run_env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.PIPE, text=True, start_new_session=True)
        try:  # (the campaign stopped while it applied the fault: its launch goes too)
            time.sleep(rng.uniform(0.2, 4.0))
            # (a launch over before its fault: 0 or 1, as it ended; else the fault's status, or 1
            # when a failure of its own had begun its shutdown)
            expected = {0, 1} if proc.poll() is not None else {1}
            if fault in ("SIGINT", "SIGTERM", "SIGKILL"):
                sig = getattr(signal, fault)
                proc.send_signal(sig)
                expected |= {-9} if sig == signal.SIGKILL else {128 + sig}
            elif fault.startswith("Ctrl-C"):
                for _ in range(2 if fault == "Ctrl-C twice" else 3):
                    proc.send_signal(signal.SIGINT)
                    time.sleep(rng.uniform(0, 0.5))
                expected |= {130}
            elif fault.startswith("kill a"):
                below = descendants(proc.pid)
                deep = [p for p in below if parent(p) not in (proc.pid, -1)] \
                    if "grand" in fault else [p for p in below if parent(p) == proc.pid]
                if deep:
                    with contextlib.suppress(psutil.Error):
                        rng.choice(deep).kill()
                time.sleep(rng.uniform(0, 1.0))
                proc.send_signal(signal.SIGINT)
                expected |= {130}
            else:  # a condition, not a moment: the launch meets it, then Ctrl-C
                proc.send_signal(signal.SIGINT)
                expected |= {130}
        except BaseException:
            proc.send_signal(signal.SIGINT)
            raise
        details = ""
        try:
            _, err = proc.communicate(timeout=HANG)
            code = proc.returncode
            outcome = "as documented" if code in expected else "exit status not documented"
            if outcome != "as documented" or "Traceback" in err:
                outcome = outcome if "Traceback" not in err else "a traceback"
                details = f"exit {code}, expected {sorted(expected)}\n{err[-1500:]}"
        except subprocess.TimeoutExpired:
            outcome = "hang"
            proc.kill()
            details = proc.communicate()[1][-1500:]
        except BaseException:  # (as above)
            proc.send_signal(signal.SIGINT)
            raise
    deadline = time.monotonic() + SETTLE
    left = carrying(tag)
    while left and time.monotonic() < deadline:
        time.sleep(0.1)
        left = carrying(tag)
    for each in left:
        details += f"\nleft: {each.pid} {' '.join(each.cmdline())[:120]}"
        with contextlib.suppress(psutil.Error):
            each.kill()
    shutil.rmtree(folder, ignore_errors=True)
    return outcome, len(left), details


def campaign(runs: int, seed: int) -> list[tuple[str, str, str]]:
    rng = random.Random(seed)
    base = Path(tempfile.mkdtemp(prefix="launcher-bench-campaign-"))
    env = {**os.environ, "LAUNCHER_RUN_DIR": str(base / "run"),
           "LAUNCHER_ROUTER_LINGER": "1"}
    env.pop("LAUNCHER_ROUTER", None)
    root = os.geteuid() == 0 and shutil.which("mount") is not None
    outcomes: Counter[str] = Counter()
    by_fault: Counter[str] = Counter()
    by_launch: Counter[str] = Counter()
    orphans = 0
    began = time.monotonic()
    try:
        for n in range(runs):
            kind = rng.choice(LAUNCHES)
            fault = rng.choice([f for f in FAULTS if root or f != "full disk"])
            if fault == "memory pressure" and kind not in ("demo", "lockstep"):
                kind = rng.choice(("demo", "lockstep"))
            outcome, left, details = one(kind, fault, rng, base, env)
            outcomes[outcome] += 1
            by_fault[fault] += 1
            by_launch[kind] += 1
            orphans += left
            if details and (outcome != "as documented" or left):
                print(f"--- run {n}: {kind}, {fault}: {outcome}, {left} left\n{details}",
                      flush=True)
            if (n + 1) % 50 == 0:
                print(f"{n + 1} runs: {dict(outcomes)}, {orphans} left", flush=True)
    finally:
        shutil.rmtree(base, ignore_errors=True)
    done = sum(outcomes.values())
    return [
        ("campaign runs", f"≥ {runs}", f"{done} in {time.monotonic() - began:.0f} s"),
        ("processes left behind", "0", f"{orphans}"),
        ("hangs", "0", f"{outcomes['hang']}"),
        ("exit statuses not as documented", "0",
         f"{outcomes['exit status not documented']}"),
        ("tracebacks", "0", f"{outcomes['a traceback']}"),
        ("runs by launch", "-", ", ".join(f"{k} {v}" for k, v in sorted(by_launch.items()))),
        ("runs by fault", "-", ", ".join(f"{k} {v}" for k, v in sorted(by_fault.items()))),
    ] + ([] if root else [("full disk", "-", "not run: mounting a tmpfs needs root")])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=56)
    args = parser.parse_args()
    signal.signal(signal.SIGINT, signal.default_int_handler)  # (launches get it at default)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # (its launch goes too)
    table(f"The fault campaign: {args.runs} runs", campaign(args.runs, args.seed))


if __name__ == "__main__":
    main()
