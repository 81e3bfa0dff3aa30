"""How a launch ends, and with what exit status.

A shutdown (an action asked, an error, a signal) runs the OnShutdown handlers, cancels the
timers that ask it, and stops every process. The first SIGINT or SIGTERM starts one with the
status 128 + the signal's number; a signal during a shutdown hurries it on (the next signal
of the escalation) and keeps its status. The launch ends once nothing runs and nothing is
pending; what its processes left running is then stopped by a `Sweep` (custody.py).
"""

from __future__ import annotations

import signal
from collections.abc import Callable

from launcher.runtime import events
from launcher.runtime.custody import Custody, Sweep
from launcher.runtime.loop import EventLoop
from launcher.runtime.process_table import ProcessTable, spec_timeouts


class Ending:
    def __init__(self, loop: EventLoop, table: ProcessTable, custody: Custody,
                 log: Callable[[str, str, str], None], emit: Callable[[events.Event], None],
                 pending: Callable[[], bool], drop_queue: Callable[[], None],
                 cancel: Callable[[], None]) -> None:
        """`pending`: whether actions, timers or loads are still to come; `drop_queue` drops
        the actions queued (before the OnShutdown handlers queue theirs); `cancel` the timers
        that end with the launch and the composable node loads."""
        self.loop, self.table, self.custody = loop, table, custody
        self.log, self.emit, self.pending = log, emit, pending
        self.drop_queue, self.cancel = drop_queue, cancel
        self.shutting_down = False
        self.finished = False
        self.error = False  # an action failed or an error was reported
        self._signal_code: int | None = None
        self._signals = 0
        self._sweep: Sweep | None = None

    @property
    def exit_code(self) -> int:
        if self._signal_code is not None:
            return self._signal_code
        return 1 if self.error or self.table.failed() else 0

    @property
    def swept_all(self) -> bool:
        """The launch's last look (the sweep) left nothing running."""
        return self.finished and not (self._sweep is not None and self._sweep.gave_up)

    def shutdown(self, reason: str) -> None:
        """End the launch: OnShutdown handlers run, timers stop, processes are stopped."""
        if self.shutting_down:
            return
        self.shutting_down = True
        self.log("DEBUG", "launch", f"shutting down: {reason}")
        self.drop_queue()
        self.emit(events.Shutdown(reason=reason))
        self.cancel()
        self.table.stop()
        self.check()

    def on_signal(self, sig: int) -> None:
        self._signals += 1
        name = signal.Signals(sig).name
        if self._signals == 1 and self.shutting_down:  # hurry on; keep its exit status
            self.log("WARN", "launch", f"{name} during the shutdown: escalating to the next "
                                       f"signal")
            self._escalate()
        elif self._signals == 1:
            self._signal_code = 128 + sig
            what = "user interrupted with ctrl-c (SIGINT)" if sig == signal.SIGINT else \
                f"received {name}"
            self.log("WARN", "launch", f"{what}: stopping all processes")
            self.shutdown(f"signal {name}")
        else:
            self.log("WARN", "launch", f"{name} again: escalating to the next signal")
            self._escalate()

    def _escalate(self) -> None:
        self.table.escalate()
        if self._sweep is not None:
            self._sweep.escalate()

    def check(self) -> None:
        """The launch ends when no process runs and no timer or action is pending, and what
        its processes left running is stopped."""
        if self.finished or self.pending() or self.table.working():
            return
        if self.table.alive():  # helpers alone, their work done
            self.shutdown("only the launch's helpers are left")
            return
        hosts = self.table.hosts
        if hosts is not None and hosts.open:  # each other host ends what is left there
            hosts.close(then=self.check)
            return
        if self._sweep is None:
            self.table.system.end_servers()  # (the launcher's own helpers: not left behind)
            left = self.custody.leftovers()
            if left:
                self._sweep = Sweep(self.custody, self.loop,
                                    lambda level, text: self.log(level, "launch", text),
                                    self.check, *spec_timeouts(self.table))
                self._sweep.start(left)
        if self._sweep is not None and not self._sweep.finished:
            return
        self.finished = True
        self.loop.stop()
