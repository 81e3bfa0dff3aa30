"""rclpy.timer: Timer (run by the executor when due) and Rate.

A timer keeps its clock's time, as rclpy's do: the node's clock (ROS time) follows `/clock`
when use_sim_time is true, so the timer is due when sim time has reached it; otherwise (and
for a steady or system clock) it keeps the monotonic clock. Calls stay on their grid: the ones
missed while nothing ran are skipped."""

from __future__ import annotations

import time
from typing import Any

from launcher.bus.timer import Grid
from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.clock import Clock, ClockType  # noqa: F401
from rclpy.context import Context  # noqa: F401
from rclpy.exceptions import (  # noqa: F401
    ExternalShutdownException,
    InvalidHandle,
    ROSInterruptException,
)
from rclpy.properties import readonly
from rclpy.time import Time
from rclpy.utilities import get_default_context  # noqa: F401

SIM_LOOK = 0.001  # s between looks at sim time while a Rate on it sleeps


class TimerInfo:
    """When a timer's call was due and when it came (a callback taking one argument gets
    it)."""

    def __init__(self, *, expected_call_time: int = 0, actual_call_time: int = 0,
                 clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        if expected_call_time < 0 or actual_call_time < 0:
            raise ValueError("call time values must not be negative")
        self._expected = Time(nanoseconds=expected_call_time, clock_type=clock_type)
        self._actual = Time(nanoseconds=actual_call_time, clock_type=clock_type)

    expected_call_time = readonly("_expected", "When the call was due.")
    actual_call_time = readonly("_actual", "When the call came.")


class Timer:
    def __init__(self, callback: Any, callback_group: Any, timer_period_ns: int,
                 clock: Any = None, *, context: Any = None, autostart: bool = True) -> None:
        self.callback, self.callback_group, self._clock = callback, callback_group, clock
        self._period = timer_period_ns / 1e9
        self._period_ns = timer_period_ns
        self._canceled = not autostart
        self._last = self._now()
        self._grid = Grid(self._period, self._last)
        self._fire = None  # set by the node: the callback run in its group

    def _now(self) -> float:
        return _seconds(self._clock)

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
        self._grid = Grid(self._period, self._now())

    def is_ready(self) -> bool:
        """Whether a call is due now."""
        return not self._canceled and self._now() >= self._grid.next

    def time_since_last_call(self) -> int:
        """Nanoseconds since the last call (or the start), on its clock."""
        return int((self._now() - self._last) * 1e9)

    def time_until_next_call(self) -> int | None:
        """Nanoseconds until the next call on its clock (None when canceled)."""
        if self._canceled:
            return None
        return int((self._grid.next - self._now()) * 1e9)

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
    return timer._grid.until(timer._now(), not _on_sim_time(timer._clock))


def take(timer: Timer) -> Any:
    """The executor's part, at a due timer: its grid moves on, and the callback to run comes
    back."""
    now = timer._now()
    timer._grid.advance(now)
    timer._last = now
    return timer._fire


def _on_sim_time(clock: Any) -> bool:
    """The clock is ROS time on /clock (a node's, with use_sim_time true)."""
    return bool(getattr(clock, "ros_time_is_active", False))


def _seconds(clock: Any) -> float:
    """Now, in seconds on `clock`: sim time when it is on /clock, else the monotonic clock."""
    return clock.now().nanoseconds / 1e9 if _on_sim_time(clock) else time.monotonic()


class Rate:
    """Sleeps so that a loop runs at `frequency` on `clock` (sim time on a node's clock when
    use_sim_time is true: then the node must be spinning elsewhere for /clock to come, as in
    rclpy); on the monotonic clock it needs nothing else."""

    def __init__(self, timer: Timer, *, context: Any) -> None:
        """Sleeps on `timer`'s period and clock (Node.create_rate makes the timer)."""
        self._clock = timer.clock
        self._grid = Grid(timer.timer_period_ns / 1e9, _seconds(self._clock))
        self._context = context

    def sleep(self) -> None:
        """Sleep out the rest of the period (ExternalShutdownException at shutdown)."""
        sim = _on_sim_time(self._clock)
        while True:
            left = self._grid.until(_seconds(self._clock), True)
            if not left:
                break
            if self._context is not None and not self._context.ok():
                raise ExternalShutdownException()
            time.sleep(SIM_LOOK if sim else min(left, 0.1))
        self._grid.advance(_seconds(self._clock))

    def destroy(self) -> None:
        """Nothing to release."""
        pass
