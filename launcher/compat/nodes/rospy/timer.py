"""rospy.timer: sleep, Rate and Timer, which end with ROSInterruptException at shutdown."""

from __future__ import annotations

import threading
import time as _time
from collections.abc import Callable
from typing import Any

from rospy.core import state
from rospy.exceptions import ROSException, ROSInterruptException
from rospy.rostime import Duration, get_rostime


def sleep(duration: Any) -> None:
    """Sleep `duration` (seconds or a Duration); ROSInterruptException at shutdown."""
    seconds = duration.to_sec() if hasattr(duration, "to_sec") else float(duration)
    end = _time.monotonic() + seconds
    while True:
        if state.shutdown.is_set():
            raise ROSInterruptException("ROS shutdown request")
        left = end - _time.monotonic()
        if left <= 0:
            return
        state.shutdown.wait(min(left, 0.1))


class Rate:
    def __init__(self, hz: float, reset: bool = False) -> None:
        if hz <= 0:
            raise ROSException("rate must be > 0")
        self.sleep_dur = Duration.from_sec(1.0 / hz)
        self._period = 1.0 / hz
        self._next = _time.monotonic() + self._period

    def remaining(self) -> Duration:
        """What is left of the current period."""
        return Duration.from_sec(max(self._next - _time.monotonic(), 0.0))

    def sleep(self) -> None:
        """Sleep out the rest of the period (the loop keeps its rate without drift)."""
        left = self._next - _time.monotonic()
        if left > 0:
            sleep(left)
        elif state.shutdown.is_set():
            raise ROSInterruptException("ROS shutdown request")
        self._next = max(self._next + self._period, _time.monotonic())


class TimerEvent:
    """What a Timer's callback is given: when the previous and this call were due
    (`*_expected`), when they came (`*_real`), and how long the previous one took in wall
    seconds (`last_duration`; None on the first call)."""

    def __init__(self, last_expected: Any, last_real: Any, current_expected: Any,
                 current_real: Any, last_duration: float | None) -> None:
        self.last_expected, self.last_real = last_expected, last_real
        self.current_expected, self.current_real = current_expected, current_real
        self.last_duration = last_duration


class Timer(threading.Thread):
    """Calls `callback(TimerEvent)` every `period` (a Duration) on a thread of its own, once
    when `oneshot`, until shutdown() or the node's shutdown."""

    def __init__(self, period: Duration, callback: Callable[[TimerEvent], Any],
                 oneshot: bool = False, reset: bool = False) -> None:
        super().__init__(daemon=True)
        self._period, self._callback = period, callback
        self._oneshot, self._reset, self._shutdown = oneshot, reset, False
        self.start()

    def shutdown(self) -> None:
        """Stop calling the callback."""
        self._shutdown = True

    def run(self) -> None:
        """The timer's thread: the callback each period, until shut down."""
        rate = Rate(1.0 / self._period.to_sec(), reset=self._reset)
        expected = get_rostime() + self._period
        last_expected = last_real = last_duration = None
        while not state.shutdown.is_set() and not self._shutdown:
            try:
                rate.sleep()
            except ROSInterruptException:
                break  # the node shut down
            if self._shutdown:
                break
            real, start = get_rostime(), _time.monotonic()
            self._callback(TimerEvent(last_expected, last_real, expected, real, last_duration))
            if self._oneshot:
                break
            last_duration = _time.monotonic() - start
            last_expected, last_real = expected, real
            expected = expected + self._period
