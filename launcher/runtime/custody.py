"""The launch's hold on every process it starts, wherever the process goes.

`begin()` marks the launch (an environment variable every process it starts inherits), makes
the launcher the child subreaper and forks the watchdog (see lineage.py and reaper.py). While
the launch runs, `tick()` notes the descendants reparented to the launcher and collects the
ones that have exited. When the launch's own processes are gone, `leftovers()` is whatever
still carries the mark or hangs below the launcher (daemons, `setsid` children, a process
that left its group); `Sweep` stops those with the escalation every process gets: SIGINT,
SIGTERM after `sigterm_timeout`, SIGKILL after `sigkill_timeout` more.
"""

from __future__ import annotations

import contextlib
import os
import signal
from collections.abc import Callable
from pathlib import Path

from launcher import lineage
from launcher.runtime import reaper
from launcher.runtime.loop import EventLoop, Timer

TICK = 0.5  # seconds between looks for adopted descendants
SWEEP_POLL = 0.05  # seconds between looks at what a sweep is stopping


class Custody:
    def __init__(self) -> None:
        self.mark: str | None = None
        self.subreaper = False
        self.watchdog: tuple[int, int] | None = None  # (pid, pipe fd)
        self.adopted: set[int] = set()

    def begin(self, environment: dict[str, str] | None = None) -> None:
        """Mark the launch (in `environment`, os.environ when None), adopt orphans, fork the
        watchdog. Call before the launch starts anything, and before any thread."""
        if self.mark is not None:
            return
        self.mark = lineage.new_mark()
        (os.environ if environment is None else environment)[self.mark] = str(os.getpid())
        self.subreaper = lineage.become_subreaper()
        self.watchdog = reaper.fork_watchdog(self.mark)

    def stamp(self, env: dict[str, str]) -> dict[str, str]:
        """`env` with the launch's mark (for a process about to start)."""
        if self.mark is not None and self.mark not in env:
            env = {**env, self.mark: str(os.getpid())}
        return env

    # --- telling the watchdog ---------------------------------------------------------------
    def group(self, pgid: int, alive: bool) -> None:
        self._tell(f"{'+' if alive else '-'}{pgid}")

    def _tell(self, line: str) -> None:
        if self.watchdog is None:
            return
        try:
            os.write(self.watchdog[1], f"{line}\n".encode())
        except OSError:  # the watchdog is gone; supervision goes on without it
            self.watchdog = None

    # --- adoption ---------------------------------------------------------------------------
    def tick(self, owned: set[int]) -> None:
        """Note new adopted children (for the watchdog) and collect exited ones. `owned`: the
        children that subprocess waits for (the launch's process leaders)."""
        keep = owned | ({self.watchdog[0]} if self.watchdog else set())
        for pid in lineage.children(os.getpid()) - keep:
            if not lineage.alive(pid):
                if lineage.reap(pid):
                    self._collected(pid)
            elif pid not in self.adopted and not lineage.is_detached(pid):
                self.adopted.add(pid)
                self._tell(f"p+{pid}")

    def leftovers(self) -> set[int]:
        """What of the launch still runs once its own processes are gone."""
        found = lineage.descendants(os.getpid())
        if self.mark is not None:
            found |= lineage.marked(self.mark)
        if self.watchdog is not None:
            found.discard(self.watchdog[0])
        for pid in lineage.children(os.getpid()) - found:  # exited adopted children
            if (self.watchdog is None or pid != self.watchdog[0]) and lineage.reap(pid):
                self._collected(pid)
        return found

    def _collected(self, pid: int) -> None:
        """An adopted child is collected: its number may now be another process's, which the
        watchdog must never end for the launch's."""
        if pid in self.adopted:
            self.adopted.discard(pid)
            self._tell(f"p-{pid}")

    # --- the end ----------------------------------------------------------------------------
    def end(self, nothing_left: bool = False) -> None:
        """Let the watchdog go. `nothing_left`: the launch found nothing of its own running
        at its end (its sweep), so the watchdog need not look for stragglers."""
        if self.watchdog is None:
            return
        if nothing_left:
            self._tell("=")
        pid, fd = self.watchdog
        self.watchdog = None
        os.close(fd)
        with contextlib.suppress(ChildProcessError):  # collected already
            os.waitpid(pid, 0)


def describe(pid: int) -> str:
    try:
        words = (Path("/proc") / str(pid) / "cmdline").read_bytes().split(b"\0")
    except OSError:
        return str(pid)
    command = " ".join(w.decode(errors="replace") for w in words if w)
    return f"{pid} ({command[:80]})" if command else str(pid)


class Sweep:
    """Stops the leftovers with the escalation, then calls `done()`."""

    def __init__(self, custody: Custody, loop: EventLoop, log: Callable[[str, str], None],
                 done: Callable[[], None], sigterm_timeout: float = 5.0,
                 sigkill_timeout: float = 5.0) -> None:
        self.custody, self.loop, self.log, self.done = custody, loop, log, done
        self._steps = [(signal.SIGINT, sigterm_timeout), (signal.SIGTERM, sigkill_timeout),
                       (signal.SIGKILL, 2.0)]
        self._timer: Timer | None = None
        self._left: set[int] = set()
        self.finished = False
        self.gave_up = False  # some were still there after SIGKILL

    def start(self, left: set[int]) -> None:
        self._left = left
        self.log("WARN", f"{len(left)} process(es) that the launch's processes left behind "
                         f"still run: {', '.join(describe(p) for p in sorted(left))}; "
                         f"stopping them")
        self.escalate()
        self.loop.call_later(SWEEP_POLL, self._poll)

    def escalate(self) -> None:
        if self.finished:
            return
        if self._timer is not None:
            self._timer.cancel()
        if not self._steps:
            self.log("ERROR", f"still running after SIGKILL: "
                              f"{', '.join(describe(p) for p in sorted(self._left))}; "
                              f"giving up on them")
            self.gave_up = True
            self._finish()
            return
        sig, wait = self._steps.pop(0)
        if sig is not signal.SIGINT:
            self.log("WARN", f"still running; sending {sig.name} to "
                             f"{', '.join(str(p) for p in sorted(self._left))}")
        lineage.signal_all(self._left, sig)
        self._timer = self.loop.call_later(wait, self.escalate)

    def _poll(self) -> None:
        if self.finished:
            return
        self._left = self.custody.leftovers()
        if not self._left:
            self._finish()
            return
        self.loop.call_later(SWEEP_POLL, self._poll)

    def _finish(self) -> None:
        self.finished = True
        if self._timer is not None:
            self._timer.cancel()
        self.done()
