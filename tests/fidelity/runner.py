"""Running one corpus case through one tool: real roslaunch, real ros2 launch, or launcher.

Each run gets a folder of its own (the case's files, the probe's records, a ROS home and a
log folder), starts the tool as a user would, waits until the launch has done what it will
do, and returns what happened: the exit status and every record the probe wrote.

A launch that would run on (roslaunch keeps its master until Ctrl-C; a respawning node comes
back) is ended with SIGINT, as a user ends it, once it has been quiet for a moment or the
case's `stop_after` has passed; its outcome is then "interrupted".
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import socket
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from launcher.compat import SITE
from tests.fidelity.corpus import Case

HERE = Path(__file__).resolve().parent
WORKSPACE = HERE / "workspace"
QUIET = 0.6  # seconds without a new probe record or output line: the launch has settled
LONGEST = 20.0  # no case runs longer than this
POLL = 0.01  # s between looks at a run (its end is timed to this, for the benchmark)


@dataclass
class Outcome:
    exit: int | str  # the exit status, or "interrupted" when the run was ended with SIGINT
    records: list[dict] = field(default_factory=list)  # the probe's, in the order of starts
    output: str = ""  # stdout and stderr together, for the reader of a failure


@dataclass(frozen=True)
class Tool:
    """How to start one launch tool for a case: its command and its environment."""

    name: str
    command: tuple[str, ...]  # before the launch file and its arguments
    env: dict[str, str]
    python: tuple[str, ...] = ()  # before a script of launch's Python API (main.py)

    def run(self, case: Case, folder: Path) -> Outcome:
        folder.mkdir(parents=True, exist_ok=True)
        for relative, text in case.files.items():
            path = folder / relative
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        out = folder / "records"
        out.mkdir(exist_ok=True)
        env = {**self.env, **case.env, "PROBE_OUT": str(out), "ROS_HOME": str(folder / "home"),
               "ROS_LOG_DIR": str(folder / "log"), "PYTHONUNBUFFERED": "1",
               "PYTHONDONTWRITEBYTECODE": "1"}
        if case.flavour == "ros1":
            env["PROBE_ROS1"] = "1"
        (folder / "home").mkdir(exist_ok=True)
        command = self.python if case.script else self.command
        argv = [*command, str(folder / case.main), *case.args]
        with open(folder / "output.txt", "wb") as log:
            proc = subprocess.Popen(argv, cwd=folder, env=env, stdout=log,
                                    stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                    start_new_session=True)
            exit_status = _wait(proc, out, folder / "output.txt", case.stop_after)
        return Outcome(exit=exit_status, records=_records(out),
                       output=(folder / "output.txt").read_text(errors="replace"))


def _wait(proc: subprocess.Popen, out: Path, output: Path, stop_after: float | None) -> int | str:
    """`stop_after` counts from the first probe record (a loaded machine starts the tool's
    first process later, not its own timing); until one comes, only LONGEST ends the run
    (every case with a `stop_after` starts a process)."""
    started = last_change = time.monotonic()
    first: float | None = None  # when the first probe record came
    seen = (-1, -1)
    while True:
        code = proc.poll()
        if code is not None:
            _end_group(proc)
            return code
        now = time.monotonic()
        state = (len(list(out.iterdir())), output.stat().st_size)
        if state != seen:
            seen, last_change = state, now
        if first is None and state[0] > 0:
            first = now
        settled = stop_after is None and state[0] > 0 and now - last_change > QUIET
        if settled or (stop_after is not None and first is not None and now - first > stop_after) \
                or now - started > LONGEST:
            _interrupt(proc)
            return "interrupted"
        time.sleep(POLL)


def _interrupt(proc: subprocess.Popen) -> None:
    try:
        os.killpg(proc.pid, signal.SIGINT)
        proc.wait(timeout=15)
    except (OSError, subprocess.TimeoutExpired):
        pass
    _end_group(proc)


def _end_group(proc: subprocess.Popen) -> None:
    """Nothing of the run outlives it (the real tools' children included)."""
    with contextlib.suppress(OSError):
        os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()


def _records(out: Path) -> list[dict]:
    return [json.loads(path.read_text()) for path in sorted(out.glob("*.json"),
                                                              key=lambda p: int(p.stem.split("-")[0]))]


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def launcher_tool(flavour: str, run_dir: Path, environ: dict[str, str] | None = None) -> Tool:
    """launcher as the user types it: `roslaunch` for ROS 1 files, `ros2 launch` for ROS 2's
    (`environ`: the environment to start from, taken in the main thread where pytest changes
    os.environ as tests begin and end)."""
    exe = Path(sys.executable).with_name("launcher")
    base = [str(exe)] if exe.exists() else [sys.executable, "-m", "launcher"]
    command = (*base, "roslaunch") if flavour == "ros1" else (*base, "launch")
    env = {key: value for key, value in (environ or os.environ).items()
           if not key.startswith(("ROS_", "AMENT_", "LAUNCHER_", "COLCON_"))}
    env.update(LAUNCHER_RUN_DIR=str(run_dir), LAUNCHER_ROUTER_LINGER="0.2",
               LAUNCHER_LOG_DIR=str(run_dir / "log"))
    if flavour == "ros1":  # where the real tools were told to look, as their users tell them
        env["ROS_PACKAGE_PATH"] = str(WORKSPACE / "src")
    else:
        env["AMENT_PREFIX_PATH"] = str(WORKSPACE / "install")
        # a script of launch's API, run as `. hooks/setup.sh` lets a shell run one
        env["PYTHONPATH"] = SITE
    return Tool("launcher", tuple(command), env, python=(sys.executable,))
