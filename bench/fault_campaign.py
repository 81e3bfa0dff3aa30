#!/usr/bin/env python3
"""The fault campaign (issue 56; bench/faults.py runs it after its own figures): runs of a real
launch, each hit by one fault, each checked for what it left running, for a hang, and for its
exit status against the documented ones (0, 1, 130 after SIGINT, 143 after SIGTERM; -9 when
the launcher itself was SIGKILLed).

Launches (each run picks one): each kind of process the launcher starts, from a sim with its
renderer to batch workers on Ray (bench/campaign_launches.py says which).

Faults: SIGINT, SIGTERM or SIGKILL of the launcher at a random moment of its first seconds;
Ctrl-C twice and three times; SIGKILL of a random child or grandchild, then Ctrl-C; the log
folder on a full 256 KiB tmpfs (root only: else said and not run); a full file-descriptor
table (`prlimit --nofile`); the sim under memory pressure (`prlimit --as` as its prefix).

    python bench/fault_campaign.py [--runs 1000] [--seed 56] [--only LAUNCH]...
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
from _harness import table
from campaign_launches import KINDS, SIMS, Places, Run, Setting, launch

from tests.support.resisting import DAEMON, STUBBORN  # (on the path campaign_launches gave)

TAG = "BENCH_CAMPAIGN_TAG"
HANG = 60.0  # seconds after its fault a launcher may take to exit
SETTLE = 10.0  # seconds its watchdog may take to end what a SIGKILLed launcher left

FAULTS = ("SIGINT", "SIGTERM", "SIGKILL", "Ctrl-C twice", "Ctrl-C three times",
          "kill a child", "kill a grandchild", "full disk", "full fd table",
          "memory pressure")


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


def victims(pid: int, run: Run, deep: bool) -> list[psutil.Process]:
    """The launcher's children (or, `deep`, its grandchildren and below), or the run's own
    where its processes are not the launcher's descendants (batch jobs on Ray's nodes)."""
    if run.victims is not None:  # (the launcher carries the run's tag too: not its own victim)
        return [p for p in run.victims(deep) if p.pid != pid]
    try:
        below = psutil.Process(pid).children(recursive=True)
    except psutil.Error:
        return []
    return [p for p in below if parent(p) not in (pid, -1)] if deep else \
        [p for p in below if parent(p) == pid]


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


def one(kind: str, fault: str, rng: random.Random, base: Path, env: dict[str, str],
        places: Places) -> tuple[str, int, str]:
    """(outcome, processes left, details) of one run."""
    folder = Path(tempfile.mkdtemp(dir=base))
    (folder / "daemon.py").write_text(DAEMON)
    (folder / "stubborn.py").write_text(STUBBORN)
    tag = uuid.uuid4().hex
    prefix = "prlimit --as=400000000" if fault == "memory pressure" else ""
    run = launch(kind, Setting(folder, rng, prefix, (TAG, tag)), places)
    run_env = {**env, **run.env, TAG: tag, "LAUNCHER_LOG_DIR": str(folder / "log")}
    argv = run.argv
    if fault == "full fd table":
        argv = ["prlimit", "--nofile=40", *argv]
    with contextlib.ExitStack() as stack:
        if fault == "full disk":
            run_env["LAUNCHER_LOG_DIR"] = str(stack.enter_context(small_disk(folder)) / "log")
        proc = subprocess.Popen(argv, cwd=folder, env=run_env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.PIPE, text=True, start_new_session=True)
        try:  # (the campaign stopped while it applied the fault: its launch goes too)
            time.sleep(rng.uniform(0.2, run.window))
            expected = {1}  # (a failure of its own had begun its shutdown)
            first = [True]

            def send(sig: int) -> None:
                """The signal; a launch already over before the fault's first signal ended
                as it ended: 0 or 1."""
                if first[0] and proc.poll() is not None:
                    expected.add(0)
                first[0] = False
                proc.send_signal(sig)

            if fault in ("SIGINT", "SIGTERM", "SIGKILL"):
                sig = getattr(signal, fault)
                send(sig)
                expected |= {-9} if sig == signal.SIGKILL else {128 + sig}
            elif fault.startswith("Ctrl-C"):
                for _ in range(2 if fault == "Ctrl-C twice" else 3):
                    send(signal.SIGINT)
                    time.sleep(rng.uniform(0, 0.5))
                expected |= {130}
            elif fault.startswith("kill a"):
                deep = victims(proc.pid, run, "grand" in fault)
                if deep:
                    with contextlib.suppress(psutil.Error):
                        rng.choice(deep).kill()
                time.sleep(rng.uniform(0, 1.0))
                send(signal.SIGINT)
                expected |= {130}
            else:  # a condition, not a moment: the launch meets it, then Ctrl-C
                send(signal.SIGINT)
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
    left = carrying(tag) + run.elsewhere()
    while left and time.monotonic() < deadline:
        time.sleep(0.1)
        left = carrying(tag) + run.elsewhere()
    for each in left:
        details += f"\nleft: {each.pid} {' '.join(each.cmdline())[:120]}"
        with contextlib.suppress(psutil.Error):
            each.kill()
    shutil.rmtree(folder, ignore_errors=True)
    return outcome, len(left), details


def campaign(runs: int, seed: int, only: list[str]) -> list[tuple[str, str, str]]:
    """The campaign's figures; `only`: the kinds of launch to run (all when empty)."""
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
    with contextlib.ExitStack() as stack:
        stack.callback(shutil.rmtree, base, ignore_errors=True)
        places = Places(stack, base)
        kinds, not_run = places.available()
        kinds = [k for k in kinds if not only or k in only]
        if not kinds:
            return [("campaign runs", f"≥ {runs}", "none: no launch of those kinds runs here"),
                    *((kind, "-", why) for kind, why in not_run)]
        for n in range(runs):
            kind = rng.choice(kinds)
            fault = rng.choice([f for f in FAULTS if root or f != "full disk"])
            if fault == "memory pressure" and kind not in SIMS:
                kind = rng.choice([k for k in SIMS if k in kinds] or kinds)
            outcome, left, details = one(kind, fault, rng, base, env, places)
            outcomes[outcome] += 1
            by_fault[fault] += 1
            by_launch[kind] += 1
            orphans += left
            if details and (outcome != "as documented" or left):
                print(f"--- run {n}: {kind}, {fault}: {outcome}, {left} left\n{details}",
                      flush=True)
            if (n + 1) % 50 == 0:
                print(f"{n + 1} runs: {dict(outcomes)}, {orphans} left", flush=True)
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
        *((kind, "-", why) for kind, why in not_run),
    ] + ([] if root else [("full disk", "-", "not run: mounting a tmpfs needs root")])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=56)
    parser.add_argument("--only", action="append", default=[], choices=KINDS,
                        help="run this kind of launch only (repeatable)")
    args = parser.parse_args()
    signal.signal(signal.SIGINT, signal.default_int_handler)  # (launches get it at default)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # (its launch goes too)
    table(f"The fault campaign: {args.runs} runs", campaign(args.runs, args.seed, args.only))


if __name__ == "__main__":
    main()
