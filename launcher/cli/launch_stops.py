"""How `launcher launch` ends besides its processes ending: `--duration` (seconds of wall
time), `--sim-duration` (seconds of sim time: each sim stops itself there and says so in its
report) and `--until NAME` (that process's exit). Each is actions appended to the launch's
description, a timer or an event handler whose reaction is a `Shutdown` giving the reason; the
exit status then follows the launch's own rules (0, or 1 when a process exited non-zero on
its own, the `--until` process included)."""

from __future__ import annotations

import contextlib
import json
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

from launcher.description.action import Action
from launcher.description.actions.shutdown import Shutdown
from launcher.description.actions.timer import TimerAction
from launcher.description.substitution import perform_text, to_text
from launcher.errors import LaunchError, UsageError, did_you_mean
from launcher.runtime.context import LaunchContext
from launcher.runtime.control import names_of

# what the sim reads (nodes/sim.py), named here too: the launch does not import the sim
STOP_AT_VARIABLE = "LAUNCHER_SIM_STOP_AT"
REPORT_DIR_VARIABLE = "LAUNCHER_SIM_REPORT_DIR"


def ending(reason: str) -> Shutdown:
    return Shutdown(reason=to_text(reason))


def duration_stop(seconds: float) -> list[Action]:
    """The launch ends `seconds` of wall time after it starts."""
    if seconds < 0:
        raise UsageError(f"--duration: expected a number ≥ 0, got {seconds:g}")
    return [TimerAction(period=seconds, actions=[ending(f"--duration {seconds:g} s elapsed")])]


def sim_duration_stop(seconds: float, environment: dict[str, str],
                      log_dir: Path) -> list[Action]:
    """The launch's processes are told (unless the user's environment tells them already) to
    stop their sims at `seconds` of sim time and to report in `<log_dir>/sim`; the launch
    ends when a process exits whose report says its sim stopped so."""
    environment.setdefault(STOP_AT_VARIABLE, repr(seconds))
    folder = Path(environment.setdefault(REPORT_DIR_VARIABLE, str(log_dir / "sim")))
    reason = f"--sim-duration {seconds:g} s of sim time reached"
    # (the event handlers' and the node's modules only when asked for: a launch's start-up)
    from launcher.description.actions.event_handlers import OnProcessExit, RegisterEventHandler

    def on_exit(event: Any, _context: LaunchContext) -> list[Action] | None:
        return [ending(reason)] if stopped_at_its_time(folder, event.pid) else None

    return [RegisterEventHandler(OnProcessExit(on_exit=on_exit))]


def stopped_at_its_time(folder: Path, pid: int | None) -> bool:
    """Whether the report of the sim that ran as process `pid` says it stopped at its stop
    time (no report, or one half written by someone else: no)."""
    if not pid:
        return False
    try:
        report = json.loads((folder / f"sim-{pid}.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(report, dict) and report.get("stopped") is True


def process_names(event: Any, context: LaunchContext) -> list[str]:
    """`names_of` the process an event is about."""
    from launcher.description.actions.node import UNSPECIFIED_NAME, Node  # (see above)

    action, node_name, executable = event.action, "", ""
    if isinstance(action, Node):
        with contextlib.suppress(RuntimeError):  # (not run yet: no name)
            node_name = action.node_name
        node_name = "" if UNSPECIFIED_NAME in node_name else node_name
        with contextlib.suppress(LaunchError):  # (its words were performed once already)
            executable = perform_text(context, to_text(action.executable))
    return names_of(event.process_name or "", list(event.cmd or ()), node_name, executable)


def until_reason(name: str, returncode: int | None) -> str:
    return f"--until {name}: it exited with code {returncode}"


def never_started(name: str, started: Iterable[Sequence[str]]) -> str:
    """What the launch says when no process named `name` started (each of `started`: the
    names of one process that did, its label's first)."""
    started = list(started)
    every = {each for names in started for each in names}
    shown = ", ".join(dict.fromkeys(names[0] for names in started if names)) or "none"
    return (f"--until {name}: no process of that name started{did_you_mean(name, every)}; "
            f"it started: {shown}")


class UntilStop:
    """`--until NAME`: the exit of a process of that name ends the launch; `check` at the end
    says when none started."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.started: list[list[str]] = []  # the names of each process started, in order

    def actions(self) -> list[Action]:
        from launcher.description.actions.event_handlers import (  # (see sim_duration_stop)
            OnProcessExit,
            OnProcessStart,
            RegisterEventHandler,
        )

        return [RegisterEventHandler(OnProcessStart(on_start=self.on_start)),
                RegisterEventHandler(OnProcessExit(on_exit=self.on_exit))]

    def on_start(self, event: Any, context: LaunchContext) -> None:
        self.started.append(process_names(event, context))

    def on_exit(self, event: Any, context: LaunchContext) -> list[Action] | None:
        if self.name not in process_names(event, context):
            return None
        return [ending(until_reason(self.name, event.returncode))]

    def check(self, exit_code: int) -> None:
        """Raise when no process of the name started, unless a signal ended the launch."""
        if exit_code < 128 and not any(self.name in names for names in self.started):
            raise UsageError(never_started(self.name, self.started))
