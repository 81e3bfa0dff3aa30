"""Timers (run by the node's executor when due) and Rate (a loop at a steady frequency).

A timer keeps the monotonic clock, or, given a node's clock on sim time (`use_sim_time`), the
sim's: it is due when `/clock` has reached it, as rclpy's timers are, so a node keeps its
timing in sim time however fast or slow the sim runs. Calls stay on their grid: one that came
late does not shift the next, and the ones missed while nothing ran are skipped."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any


class Grid:
    """Calls every `period` seconds of a clock: how long until the next, and the one after it
    (the next point of the grid after now: a late call does not shift the next, the missed
    ones are skipped). Time that goes back (a sim reset) starts the grid again."""

    def __init__(self, period: float, now: float) -> None:
        self.period, self.next = period, now + period

    def until(self, now: float, wall: bool) -> float | None:
        """Seconds until the next call (0: now); on a sim's clock, None while it is not due
        (only a `/clock` that moves the time can make it due)."""
        if now < self.next - self.period:
            self.next = now + self.period
        if now >= self.next:
            return 0.0
        return self.next - now if wall else None

    def advance(self, now: float) -> None:
        missed = int((now - self.next) // self.period)
        self.next += self.period * (max(missed, 0) + 1)


class Timer:
    def __init__(self, period: float, callback: Callable[[], None], clock: Any = None) -> None:
        self.period, self.callback = period, callback
        self._sim = clock if clock is not None and clock.use_sim_time else None
        self.grid = Grid(period, self.now())
        self.cancelled = False

    @property
    def next(self) -> float:
        return self.grid.next

    def now(self) -> float:
        """Its time, in seconds: the sim's for a timer on sim time, else the monotonic clock."""
        return self._sim.now().nanoseconds / 1e9 if self._sim is not None else time.monotonic()

    def wait(self) -> float | None:
        """Wall seconds until it is due (0: now); None while it waits for sim time to move
        (the `/clock` that moves it is work that wakes the executor)."""
        return self.grid.until(self.now(), self._sim is None)

    def fire(self) -> None:
        """Run the callback; the next call is the next point of its grid."""
        self.grid.advance(self.now())
        self.callback()

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
