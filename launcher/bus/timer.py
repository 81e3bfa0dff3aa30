"""Timers (run by the node's executor when due) and Rate (a loop at a steady frequency), both
on the monotonic clock: no drift."""

from __future__ import annotations

import time
from collections.abc import Callable


class Timer:
    def __init__(self, period: float, callback: Callable[[], None]) -> None:
        self.period, self.callback = period, callback
        self.next = time.monotonic() + period
        self.cancelled = False

    def cancel(self) -> None:
        self.cancelled = True


class Rate:
    """Sleep so that a loop runs at `hz`, against a monotonic clock (no drift)."""

    def __init__(self, hz: float) -> None:
        self.period = 1.0 / hz
        self._next = time.monotonic() + self.period

    def sleep(self) -> None:
        delay = self._next - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        self._next = max(self._next + self.period, time.monotonic())
