"""Ending a job's whole tree: its launcher's group by SIGINT, SIGTERM, SIGKILL (launcher ends
its own processes at the first), then whatever still carries the job's mark."""

from __future__ import annotations

import contextlib
import os
import signal
import time

from launcher import lineage
from launcher.runtime.custody import describe

STOP_STEPS = ((signal.SIGINT, 10.0), (signal.SIGTERM, 3.0), (signal.SIGKILL, 0.0))


class Escalation:
    """The stop steps for one process group, stepped by the host's loop."""

    def __init__(self, pgid: int, clock: object = time.monotonic) -> None:
        self.pgid = pgid
        self.clock = clock
        self.step = -1
        self.next_at = 0.0

    @property
    def begun(self) -> bool:
        return self.step >= 0

    def hurry(self) -> None:
        """The next signal now (the stop was asked again: a second Ctrl-C)."""
        self.next_at = 0.0

    def poll(self) -> None:
        """Send the next signal when its time has come (the first at once)."""
        now = self.clock()  # type: ignore[operator]
        if self.step + 1 >= len(STOP_STEPS) or (self.begun and now < self.next_at):
            return
        self.step += 1
        sig, wait = STOP_STEPS[self.step]
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.killpg(self.pgid, sig)
        self.next_at = now + wait


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
