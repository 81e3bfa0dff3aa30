"""Children that try to escape a launch or resist its stop, for the custody tests and the fault
campaign (bench/fault_campaign.py): a process that leaves its group or session, a daemon, one
that ignores SIGINT or SIGTERM, a crash, a failure, a respawn storm."""

from __future__ import annotations

import random
import sys
from collections.abc import Sequence
from pathlib import Path

PY = sys.executable

# Leaves its process group and session twice over (a double-forking daemon), and sleeps.
DAEMON = """
import os, time
if os.fork():
    os._exit(0)
os.setsid()
if os.fork():
    os._exit(0)
time.sleep(120)
"""
STUBBORN = """
import signal, sys, time
for name in sys.argv[1:]:
    signal.signal(getattr(signal, name), signal.SIG_IGN)
time.sleep(120)
"""
KINDS = {
    "sleeper": "sleep 120",
    "setsid": "sh -c 'setsid sleep 120 & sleep 120'",
    "job control": "sh -c 'set -m; sleep 120 & sleep 120'",
    "daemon": f"{PY} {{here}}daemon.py",
    "ignores SIGINT": f"{PY} {{here}}stubborn.py SIGINT",
    "ignores both": f"{PY} {{here}}stubborn.py SIGINT SIGTERM",
    "crash": "sh -c 'sleep 0.1; kill -SEGV $$'",
    "fails": "sh -c 'exit 3'",
    "respawn storm": "sh -c 'sleep 120 & exit 0'",
}


def children_launch(rng: random.Random, most: int, timeout: float,
                    machines: Sequence[str] = (), folder: Path | None = None) -> str:
    """A launch file of 1 to `most` children of the kinds above (daemon.py and stubborn.py
    beside it, or in `folder`), each stopped with `timeout` seconds between its signals; with
    `machines`, each child on one of them (machines of the same names, at those addresses)."""
    lines = [*(["extensions: [launcher]"] if machines else []), "launch:",
             *(f"  - machine: {{name: {name}, address: {name}}}" for name in machines)]
    for _ in range(rng.randint(1, most)):
        kind = rng.choice(list(KINDS))
        here = f"{folder}/" if folder is not None else ""
        cmd = KINDS[kind].format(here=here).replace('"', '\\"')
        extra = ", respawn: true, respawn_delay: 0" if kind == "respawn storm" else ""
        if machines:
            extra += f", machine: {rng.choice(machines)}"
        lines.append(f'  - executable: {{cmd: "{cmd}", sigterm_timeout: {timeout:g}, '
                     f'sigkill_timeout: {timeout:g}{extra}}}')
    return "\n".join(lines) + "\n"
