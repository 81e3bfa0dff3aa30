"""rospy.timer: sleep and Rate, which end with ROSInterruptException at shutdown."""

from __future__ import annotations

import time as _time
from typing import Any

from rospy.core import state
from rospy.exceptions import ROSException, ROSInterruptException
from rospy.rostime import Duration


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
