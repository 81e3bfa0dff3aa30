#!/usr/bin/env python3
"""The lost-signal stress test (issue 56): launches, each sent SIGINT or SIGTERM at a random
moment of its first second, with two CPU hogs beside them.

Each launch runs a file with a plain process, a daemonising grandchild and a node that starts
the graph's router (the start-up's every path: loading, spawning, the router). A launch whose
launcher still runs `--wait` seconds after its signal has lost it: its Python stacks are
printed (py-spy, when on PATH) and it is killed. After each exit, whatever still carries the
run's own environment variable (the router aside, which is nobody's launch's) is left behind.

    python bench/signals.py [--runs 2000] [--wait 20] [--hogs 2]

Target: 0 lost, 0 left running, every exit status 130 (SIGINT) or 143 (SIGTERM); a signal
landing before the launcher's first lines have put its handlers in place ends it by the
signal itself (the shell shows the same 130 or 143), counted apart.

The launches start as from a terminal's shell: SIGINT at its default. (A shell's background
job inherits SIGINT ignored, and the kernel discards a SIGINT that lands before the launcher's
first lines catch it: that is the job's inheritance, not a lost signal, and it was the second
cause this test found.)
"""

from __future__ import annotations

import argparse
import os
import random
import re
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

LAUNCH = """
launch:
  - executable: {cmd: "sleep 120", sigterm_timeout: 0.5}
  - executable: {cmd: "sh -c 'setsid sleep 120 & sleep 120'", sigterm_timeout: 0.5}
  - node: {pkg: tf2_ros, exec: static_transform_publisher, name: fixed,
           args: "--frame-id a --child-frame-id b", sigterm_timeout: 0.5}
"""
RUN_VARIABLE = "BENCH_SIGNAL_RUN"
LOST = "lost (still running)"
DOCUMENTED = "exited as documented"
BY_SIGNAL = "ended by the signal itself (before its handlers)"
BY_PYTHON = "ended by Python's own start-up error (before its handlers)"


def hog() -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-c", "while True: pass"],
                            start_new_session=True)


def carrying(value: str) -> list[psutil.Process]:
    """The processes whose environment holds RUN_VARIABLE=value, the graph's router aside."""
    found = []
    for proc in psutil.process_iter():
        try:
            if proc.environ().get(RUN_VARIABLE) != value:
                continue
            if "launcher.bus.router" in " ".join(proc.cmdline()):
                continue
            found.append(proc)
        except (psutil.NoSuchProcess, psutil.AccessDenied, psutil.ZombieProcess):
            continue
    return found


def catches_term(pid: int) -> bool:
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return False
    caught = int(re.search(r"SigCgt:\s*([0-9a-f]+)", status).group(1), 16)
    return bool(caught & (1 << (signal.SIGTERM - 1)))


def signal_state(pid: int) -> str:
    """Its signal masks as /proc shows them (blocked, pending, ignored, caught)."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return "(gone)"
    return " ".join(re.findall(r"^(?:SigQ|SigPnd|ShdPnd|SigBlk|SigIgn|SigCgt):\s*\S+", status,
                               re.M))


def launch_log(folder: Path, pid: int) -> str:
    """The end of the launch's own log (it flushes it every half second)."""
    found = sorted(folder.glob(f"log/*-{pid}/launch.log"))
    return found[0].read_text()[-3000:] if found else "(no log)"


def stacks(pid: int) -> str:
    spy = shutil.which("py-spy")
    if spy is None:
        return "(py-spy is not on PATH: no stacks)"
    done = subprocess.run([spy, "dump", "--pid", str(pid), "--locals"], capture_output=True,
                          text=True, timeout=60)
    return done.stdout + done.stderr


def one(folder: Path, env: dict[str, str], rng: random.Random, sig: int,
        wait: float) -> tuple[str, int, str]:
    """(outcome, left behind, details) of one launch signalled at a random moment."""
    run = uuid.uuid4().hex
    traced = folder / f"trace-{run}.txt"  # (what its handlers saw: printed when it is lost)
    proc = subprocess.Popen([*launcher_cmd(), "launch", "-n", str(folder / "s.launch.yaml")],
                            env={**env, RUN_VARIABLE: run, "LAUNCHER_SIGNAL_TRACE": str(traced)},
                            cwd=folder, start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    started = time.monotonic()
    delay = rng.uniform(0, 1.0)
    early = True
    while time.monotonic() - started < delay:
        early = early and not catches_term(proc.pid)
        time.sleep(0.002)
    early = early and not catches_term(proc.pid)
    proc.send_signal(sig)
    sent_at = time.time()  # (to set beside its log's times)
    details = ""
    try:
        _, err = proc.communicate(timeout=wait)
        code = proc.returncode
        if code in (-sig,) and early:
            outcome = BY_SIGNAL
        elif code == 1 and early and "Fatal Python error" in err:
            outcome = BY_PYTHON
        elif code == 128 + sig:
            outcome = DOCUMENTED
        else:
            outcome = f"exited {code}: not as documented"
            details = err[-2000:]
    except BaseException as exc:
        if not isinstance(exc, subprocess.TimeoutExpired):  # the bench stopped while it
            proc.kill()  # waited: the launch goes with it
            raise
        outcome = LOST
        details = (f"signal {signal.Signals(sig).name} at {delay:.3f} s (at {sent_at:.4f})\n"
                   f"{signal_state(proc.pid)}\n{stacks(proc.pid)}\nits log:\n"
                   f"{launch_log(folder, proc.pid)}\nits handlers saw:\n"
                   f"{traced.read_text() if traced.exists() else '(nothing)'}")
        proc.kill()
        details += "\nits stderr:\n" + proc.communicate()[1][-3000:]
    traced.unlink(missing_ok=True)
    deadline = time.monotonic() + 5.0  # (a SIGKILLed launcher's watchdog takes a moment)
    left = carrying(run)
    while left and time.monotonic() < deadline:
        time.sleep(0.1)
        left = carrying(run)
    for each in left:
        details += f"\nleft: {each.pid} {' '.join(each.cmdline())}"
        each.kill()
    return outcome, len(left), details


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=2000)
    parser.add_argument("--wait", type=float, default=20.0,
                        help="seconds after its signal a launcher may take to exit")
    parser.add_argument("--hogs", type=int, default=2)
    parser.add_argument("--seed", type=int, default=56)
    args = parser.parse_args()
    signal.signal(signal.SIGINT, signal.default_int_handler)  # (see above; exec resets it)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # (its hogs and launch go too)
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-signals-"))
    (folder / "s.launch.yaml").write_text(LAUNCH)
    env = {**os.environ, "LAUNCHER_LOG_DIR": str(folder / "log"),
           "LAUNCHER_RUN_DIR": str(folder / "run")}
    env.pop("LAUNCHER_ROUTER", None)
    rng = random.Random(args.seed)
    hogs = [hog() for _ in range(args.hogs)]
    outcomes: Counter[str] = Counter()
    left_total = 0
    began = time.monotonic()
    try:
        for n in range(args.runs):
            sig = (signal.SIGINT, signal.SIGTERM)[n % 2]
            outcome, left, details = one(folder, env, rng, sig, args.wait)
            outcomes[outcome] += 1
            left_total += left
            if details:
                print(f"--- run {n}: {outcome}, {left} left\n{details}", flush=True)
            if (n + 1) % 100 == 0:
                print(f"{n + 1} runs: {dict(outcomes)}, {left_total} left", flush=True)
    finally:
        for each in hogs:
            each.kill()
        shutil.rmtree(folder, ignore_errors=True)
    runs = sum(outcomes.values())
    lost = outcomes[LOST]
    wrong = sum(v for k, v in outcomes.items() if k.startswith("exited ") and
                "not as documented" in k)
    table(f"The lost signal: {runs} launches signalled in their first second, "
          f"{args.hogs} CPU hogs beside them ({time.monotonic() - began:.0f} s)", [
              ("launches", f"{args.runs}", f"{runs}"),
              ("lost signals", "0", f"{lost}"),
              ("processes left running", "0", f"{left_total}"),
              ("exit status not as documented", "0", f"{wrong}"),
              ("exited 130/143 as documented", "-", f"{outcomes[DOCUMENTED]}"),
              ("ended by the signal before its handlers", "-", f"{outcomes[BY_SIGNAL]}"),
              ("ended by Python's start-up error before its handlers (1)", "-",
               f"{outcomes[BY_PYTHON]}"),
          ])


if __name__ == "__main__":
    main()
