"""The user's hand on a running launch (`launcher ps`, `stop`, `start`, `restart`, `logs`): what
the launch answers about its processes, and what it does to one of them. The graph's face of it
(services of the launch's own node, behind the graph's token) is cli/launch_control.py's; this
is the launch's side, run on its loop.

A stop by the user is not an exit of the process's own: no ProcessExited or ExecutionComplete
reaches the event handlers (a `required` process does not end the launch, respawn does not
fire), the process is listed as `stopped`, and the launch runs on while it may be started again.
A start (and a restart's start) is a start like the first: ProcessStarted, and a container's
composable nodes loaded again.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Sequence
from typing import NamedTuple

from launcher.errors import did_you_mean
from launcher.runtime.figures import PERIOD, Figures
from launcher.runtime.loop import EventLoop
from launcher.runtime.process import ManagedProcess, State
from launcher.runtime.process_table import ProcessTable
from launcher.runtime.recent import Line, Recent

VERBS = ("stop", "start", "restart")


class Row(NamedTuple):
    name: str
    names: list[str]
    node: str
    pid: int
    host: str
    state: str
    exit_code: int | None
    restarts: int
    uptime: float
    cpu: float  # -1: unknown (another host's)
    memory: int  # -1: unknown


class Refused(Exception):
    """What the launch says instead of doing what it was asked."""


def label_base(label: str) -> str:
    """A process's label without the number the launch gave it (`driver-3`: driver)."""
    return re.sub(r"-\d+$", "", label)


def names_of(label: str, argv: Sequence[str], node_name: str = "",
             executable: str = "") -> list[str]:
    """The names a process goes by, its label's first: the label without its number, the
    node's name, its package executable, and its program's file name."""
    program = os.path.basename(argv[0]) if argv else ""
    found = [label_base(label), node_name.rsplit("/", 1)[-1], executable, program]
    return list(dict.fromkeys(name for name in found if name))


def state_of(process: ManagedProcess) -> str:
    if process.held:
        return "stopping" if process.state is State.STOPPING else "stopped"
    return {State.STARTING: "starting", State.RUNNING: "running", State.BACKOFF: "respawning",
            State.STOPPING: "stopping", State.EXITED: "exited",
            State.FATAL: "failed"}[process.state]


class ProcessControl:
    def __init__(self, table: ProcessTable, loop: EventLoop, figures: Figures,
                 recent: Recent, log: Callable[[str, str, str], None]) -> None:
        self.table, self.loop, self.figures, self.recent = table, loop, figures, recent
        self.log = log
        self.host = os.uname().nodename
        self.started = loop.time()
        loop.open_posting()  # (the graph's requests come from another thread)
        self._timer = loop.call_later(PERIOD, self._sample)

    # --- what it answers ----------------------------------------------------------------------
    def rows(self) -> list[Row]:
        now = self.loop.time()
        rows = []
        for process in self.table.processes:
            spec, running = process.spec, process.leader_running
            local = spec.machine is None or spec.machine.local
            figure = self.figures.now.get(process.pid or 0) if local and running else None
            names = [process.label, *names_of(process.label, spec.argv, spec.node_name)]
            rows.append(Row(
                process.label, list(dict.fromkeys(names)), spec.node_name,
                process.pid or 0 if running else 0,
                self.host if local else spec.machine.name,  # type: ignore[union-attr]
                state_of(process), None if running else process.returncode,
                process.restarts, now - process.started_at if running else 0.0,
                figure.cpu if figure else -1.0,  # (another host's, or not sampled yet)
                figure.memory if figure else -1))
        return rows

    def output(self, name: str, after: int) -> tuple[int, list[Line]]:
        self.find(name)
        return self.recent.after(name, after)

    def find(self, name: str) -> ManagedProcess:
        """The process labelled `name` (the client has picked it from the rows)."""
        for process in self.table.processes:
            if process.label == name:
                return process
        labels = [p.label for p in self.table.processes]
        raise Refused(f"this launch has no process '{name}'{did_you_mean(name, labels)}")

    # --- what it does -------------------------------------------------------------------------
    def act(self, verb: str, name: str, uid: int) -> str:
        """Do `verb` to the process `name`; what was done (Refused: why not)."""
        if verb not in VERBS:
            raise Refused(f"unknown verb '{verb}'{did_you_mean(verb, VERBS)}: expected one "
                          f"of {', '.join(VERBS)}")
        if uid != os.getuid():
            raise Refused(f"'{name}' is not yours: this launch (pid {os.getpid()}) runs as "
                          f"user {os.getuid()}, and you are user {uid}")
        if self.table.closing:
            raise Refused("the launch is shutting down")
        process = self.find(name)
        if verb == "stop":
            if not process.alive:
                raise Refused(f"'{name}' is not running (it is {state_of(process)})")
            self.log("INFO", process.shown, "stopped by the user")
            self.table.hold(process)
            return f"stopping {name}"
        if verb == "start":
            if process.alive:
                raise Refused(f"'{name}' is already running (pid {process.pid}); "
                              f"`launcher restart {name}` stops it and starts it again")
            self.log("INFO", process.shown, "started by the user")
            if not self.table.start_again(process):
                raise Refused(f"'{name}' could not start (see the launch's log)")
            return f"started {name} (pid {process.pid})"
        self.log("INFO", process.shown, "restarted by the user")
        if not self.table.restart(process):
            raise Refused(f"'{name}' could not start (see the launch's log)")
        return f"restarting {name}"

    # --- the figures --------------------------------------------------------------------------
    def _sample(self) -> None:
        running = [(p.label, p.pid) for p in self.table.processes
                   if p.leader_running and p.pid and
                   (p.spec.machine is None or p.spec.machine.local)]
        self.figures.sample(running)  # type: ignore[arg-type]
        self._timer = self.loop.call_later(PERIOD, self._sample)

    def close(self) -> None:
        self._timer.cancel()
        self.figures.close()
