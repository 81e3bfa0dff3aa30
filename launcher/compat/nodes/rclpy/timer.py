"""rclpy.timer: Timer (run by the executor when due, on the monotonic clock) and Rate."""

from __future__ import annotations

import time
from typing import Any


class Timer:
    def __init__(self, callback: Any, callback_group: Any, timer_period_ns: int,
                 clock: Any = None, *, context: Any = None, autostart: bool = True) -> None:
        self.callback, self.callback_group, self._clock = callback, callback_group, clock
        self._period = timer_period_ns / 1e9
        self._period_ns = timer_period_ns
        self._canceled = not autostart
        self._last = time.monotonic()
        self._next = self._last + self._period
        self._fire = None  # set by the node: the callback run in its group

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
        self._next = time.monotonic() + self._period

    def is_ready(self) -> bool:
        """Whether a call is due now."""
        return not self._canceled and time.monotonic() >= self._next

    def time_since_last_call(self) -> int:
        """Nanoseconds since the last call (or the start)."""
        return int((time.monotonic() - self._last) * 1e9)

    def time_until_next_call(self) -> int | None:
        """Nanoseconds until the next call (None when canceled)."""
        if self._canceled:
            return None
        return int((self._next - time.monotonic()) * 1e9)

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


def due(timer: Timer) -> float:
    """When the timer is due next, on the monotonic clock."""
    return timer._next


def take(timer: Timer, now: float) -> Any:
    """The executor's part, at a due timer: its grid moves one period on (never behind
    `now`), and the callback to run comes back."""
    timer._next = max(timer._next + timer._period, now)
    timer._last = now
    return timer._fire


class Rate:
    """Sleeps so that a loop runs at `frequency`; needs no executor spinning elsewhere."""

    def __init__(self, frequency: float, *, context: Any = None) -> None:
        if frequency <= 0:
            raise ValueError("frequency must be > 0")
        self._period = 1.0 / frequency
        self._next = time.monotonic() + self._period
        self._context = context

    def sleep(self) -> None:
        """Sleep out the rest of the period (ExternalShutdownException at shutdown)."""
        from rclpy.executors import ExternalShutdownException

        while True:
            left = self._next - time.monotonic()
            if left <= 0:
                break
            if self._context is not None and not self._context.ok():
                raise ExternalShutdownException()
            time.sleep(min(left, 0.1))
        self._next = max(self._next + self._period, time.monotonic())

    def destroy(self) -> None:
        """Nothing to release."""
        pass
