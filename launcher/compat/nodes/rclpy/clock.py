"""rclpy.clock: Clock, ROSClock (sim time when the node's use_sim_time is true)."""

from __future__ import annotations

import time as _time
from typing import Any

from rclpy.clock_type import ClockType
from rclpy.duration import Duration
from rclpy.time import Time

__all__ = ["Clock", "ClockType", "ROSClock"]


class Clock:
    def __init__(self, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        self._clock_type = clock_type

    @property
    def clock_type(self) -> ClockType:
        """The clock's ClockType."""
        return self._clock_type

    def _now_ns(self) -> int:
        if self._clock_type == ClockType.STEADY_TIME:
            return _time.monotonic_ns()
        return _time.time_ns()

    def now(self) -> Time:
        """The clock's current Time."""
        return Time(nanoseconds=self._now_ns(), clock_type=self._clock_type)

    def sleep_for(self, rel_time: Duration, context: Any = None) -> bool:
        """Sleep `rel_time` on this clock; False if the context shut down first."""
        return self.sleep_until(self.now() + rel_time, context)

    def sleep_until(self, until: Time, context: Any = None) -> bool:
        """Sleep until `until` on this clock; False if the context shut down first."""
        from rclpy.utilities import get_default_context

        context = context or get_default_context()
        while context.ok():
            left = until.nanoseconds - self._now_ns()
            if left <= 0:
                return True
            _time.sleep(min(left / 1e9, 0.05))
        return False

    def __repr__(self) -> str:
        return f"Clock(clock_type={self._clock_type.name})"


class ROSClock(Clock):
    """ROS time: the node's `/clock` when use_sim_time is true, else the system time."""

    def __init__(self, source: Any = None) -> None:
        super().__init__(clock_type=ClockType.ROS_TIME)
        self._source = source  # launcher's node clock

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the time comes from /clock (use_sim_time)."""
        return bool(self._source is not None and self._source.use_sim_time)

    def _now_ns(self) -> int:
        if self._source is not None:
            return self._source.now().nanoseconds
        return _time.time_ns()
