"""Ending a job's whole tree: its launcher's group by SIGINT, SIGTERM, SIGKILL (launcher ends
its own processes at the first), then whatever still carries the job's mark."""

from __future__ import annotations

import contextlib
import os
import signal
import time
from typing import Any

from launcher import lineage
from launcher.runtime.custody import describe
from launcher.runtime.loop import EventLoop

STOP_STEPS = ((signal.SIGINT, 10.0), (signal.SIGTERM, 3.0), (signal.SIGKILL, 0.0))


class Escalation:
    """The stop steps for one process group, each after the last one's wait, on the loop."""

    def __init__(self, pgid: int, loop: EventLoop) -> None:
        self.pgid = pgid
        self.loop = loop
        self.step = 0  # the next one
        self.timer: Any = None

    def start(self) -> None:
        """The first signal now, the others after their waits (idempotent)."""
        if self.step == 0:
            self._next()

    def hurry(self) -> None:
        """The next signal now (the stop was asked again: a second Ctrl-C)."""
        if self.timer is not None:
            self.timer.cancel()
        self._next()

    def _next(self) -> None:
        if self.step >= len(STOP_STEPS):
            return
        sig, wait = STOP_STEPS[self.step]
        self.step += 1
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.killpg(self.pgid, sig)
        self.timer = self.loop.call_later(wait, self._next)


def sweep(mark: str, grace: float = 1.0, limit: float = 5.0, settle: float = 1.0
          ) -> list[str]:
    """End every process carrying `mark` that has not gone by itself within `settle` seconds:
    SIGTERM, SIGKILL after `grace`; looked for again until a look finds nothing. The names of
    what had to be ended. The job's router (detached, on the job's private graph) is told to
    go at once and not waited for: the watchdog sees it gone."""
    def left() -> set[int]:
        return {pid for pid in lineage.marked(mark) if not lineage.is_detached(pid)}

    lineage.signal_all(lineage.marked(mark) - left(), signal.SIGTERM)
    until = time.monotonic() + settle
    while left() and time.monotonic() < until:
        _reap_any()
        time.sleep(0.02)
    found: dict[int, str] = {}  # pid → what it was
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline and (pids := left()):
        for pid in pids - found.keys():
            found[pid] = describe(pid)
        lineage.signal_all(pids, signal.SIGTERM)
        until = time.monotonic() + grace
        while time.monotonic() < until and left():
            _reap_any()
            time.sleep(0.05)
        lineage.signal_all(left(), signal.SIGKILL)
        _reap_any()
    return [found[pid] for pid in sorted(found)]


def _reap_any() -> None:
    """Collect exited orphans (the host is their subreaper)."""
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return
