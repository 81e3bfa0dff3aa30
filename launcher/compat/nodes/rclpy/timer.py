"""rclpy.timer: Timer (run by the executor when due) and Rate.

A timer keeps its clock's time, as rclpy's do: the node's clock (ROS time) follows `/clock`
when use_sim_time is true, so the timer is due when sim time has reached it; otherwise (and
for a steady or system clock) it keeps the monotonic clock. Calls stay on their grid: the ones
missed while nothing ran are skipped."""

from __future__ import annotations

import time
from typing import Any

SIM_LOOK = 0.001  # s between looks at sim time while a Rate on it sleeps


class Timer:
    def __init__(self, callback: Any, callback_group: Any, timer_period_ns: int,
                 clock: Any = None, *, context: Any = None, autostart: bool = True) -> None:
        self.callback, self.callback_group, self._clock = callback, callback_group, clock
        self._period = timer_period_ns / 1e9
        self._period_ns = timer_period_ns
        self._canceled = not autostart
        self._last = self._now()
        self._next = self._last + self._period
        self._fire = None  # set by the node: the callback run in its group

    def _now(self) -> float:
        """Seconds on its clock: sim time when that is ROS time on /clock, else monotonic."""
        if getattr(self._clock, "ros_time_is_active", False):
            return self._clock.now().nanoseconds / 1e9
        return time.monotonic()

    @property
    def timer_period_ns(self) -> int:
        """The period, in nanoseconds (setting it resets the timer)."""
        return self._period_ns

    @timer_period_ns.setter
    def timer_period_ns(self, value: int) -> None:
        """The period, in nanoseconds (setting it resets the timer)."""
        self._period_ns, self._period = value, value / 1e9
        self.reset()

    @property
    def clock(self) -> Any:
        """The clock given at creation."""
        return self._clock

    def cancel(self) -> None:
        """Stop calling back until reset()."""
        self._canceled = True

    def is_canceled(self) -> bool:
        """Whether the timer is canceled."""
        return self._canceled

    def reset(self) -> None:
        """Start again: the next call one period from now."""
        self._canceled = False
        self._next = self._now() + self._period

    def is_ready(self) -> bool:
        """Whether a call is due now."""
        return not self._canceled and self._now() >= self._next

    def time_since_last_call(self) -> int:
        """Nanoseconds since the last call (or the start), on its clock."""
        return int((self._now() - self._last) * 1e9)

    def time_until_next_call(self) -> int | None:
        """Nanoseconds until the next call on its clock (None when canceled)."""
        if self._canceled:
            return None
        return int((self._next - self._now()) * 1e9)

    def destroy(self) -> None:
        """Stop the timer for good."""
        self._canceled = True

    def __enter__(self) -> Timer:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.destroy()


def bind(timer: Timer, run: Any) -> None:
    """The node's part: the callback as run in its group (what `take` hands the executor)."""
    timer._fire = run


def due(timer: Timer) -> float | None:
    """Wall seconds until the timer is due (0: now); None while it waits for sim time to move
    (the `/clock` that moves it is work that wakes the executor)."""
    now = timer._now()
    if now < timer._next - timer._period:  # time went back (a sim reset): start again
        timer._next = now + timer._period
    if now >= timer._next:
        return 0.0
    return None if getattr(timer._clock, "ros_time_is_active", False) else timer._next - now


def take(timer: Timer) -> Any:
    """The executor's part, at a due timer: the next call is the next point of its grid after
    now, and the callback to run comes back."""
    now = timer._now()
    missed = int((now - timer._next) // timer._period)
    timer._next += timer._period * (max(missed, 0) + 1)
    timer._last = now
    return timer._fire


class Rate:
    """Sleeps so that a loop runs at `frequency` on `clock` (sim time on a node's clock when
    use_sim_time is true: then the node must be spinning elsewhere for /clock to come, as in
    rclpy); on the monotonic clock it needs nothing else."""

    def __init__(self, frequency: float, *, clock: Any = None, context: Any = None) -> None:
        if frequency <= 0:
            raise ValueError("frequency must be > 0")
        self._period = 1.0 / frequency
        self._clock = clock
        self._next = self._now() + self._period
        self._context = context

    def _now(self) -> float:
        if getattr(self._clock, "ros_time_is_active", False):
            return self._clock.now().nanoseconds / 1e9
        return time.monotonic()

    def sleep(self) -> None:
        """Sleep out the rest of the period (ExternalShutdownException at shutdown)."""
        from rclpy.executors import ExternalShutdownException

        sim = getattr(self._clock, "ros_time_is_active", False)
        while True:
            left = self._next - self._now()
            if left <= 0:
                break
            if self._context is not None and not self._context.ok():
                raise ExternalShutdownException()
            time.sleep(SIM_LOOK if sim else min(left, 0.1))
        now = self._now()
        missed = int((now - self._next) // self._period)
        self._next += self._period * (max(missed, 0) + 1)

    def destroy(self) -> None:
        """Nothing to release."""
        pass
