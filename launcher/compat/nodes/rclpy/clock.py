"""rclpy.clock: Clock, ROSClock (sim time when the node's use_sim_time is true), and the
time jumps a clock reports to the callbacks made with `create_jump_callback` (jumps.py)."""

from __future__ import annotations

import time as _time
from collections.abc import Callable
from typing import Any

from rclpy.clock_type import ClockType
from rclpy.context import Context, get_default_context  # noqa: F401 - as rclpy's offers it
from rclpy.duration import Duration
from rclpy.exceptions import NotInitializedException  # noqa: F401
from rclpy.jumps import (  # noqa: F401 - as rclpy's module offers them
    ClockChange,
    JumpHandle,
    JumpThreshold,
    TimeJump,
    TimeJumpDictionary,
    jump,
)
from rclpy.time import Time

__all__ = ["Clock", "ClockType", "ROSClock"]


class Clock:
    def __init__(self, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        self._clock_type = clock_type
        self.jump_handles: list[JumpHandle] = []

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

    def create_jump_callback(self, threshold: JumpThreshold, *,
                             pre_callback: Callable[[], None] | None = None,
                             post_callback: Callable[[TimeJump], None] | None = None
                             ) -> JumpHandle:
        """Call `pre_callback()` before and `post_callback(TimeJump)` after each jump of this
        clock that crosses `threshold`, until the handle is unregistered."""
        def post(jumped: TimeJumpDictionary) -> None:
            assert post_callback is not None
            post_callback(TimeJump(jumped["clock_change"],
                                   Duration(nanoseconds=jumped["delta"])))
        return JumpHandle(clock=self, threshold=threshold, pre_callback=pre_callback,
                          post_callback=post if callable(post_callback) else None)

    def sleep_for(self, rel_time: Duration, context: Any = None) -> bool:
        """Sleep `rel_time` on this clock; False if the context shut down first."""
        return self.sleep_until(self.now() + rel_time, context)

    def sleep_until(self, until: Time, context: Any = None) -> bool:
        """Sleep until `until` on this clock; False if the context shut down first."""
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
    """ROS time: the node's `/clock` when use_sim_time is true, else the system time. A clock
    of no node follows the time a TimeSource sets while ROS time is active."""

    def __init__(self, source: Any = None, *,
                 follow: Callable[[ROSClock], Any] | None = None) -> None:
        """`source`: launcher's node clock; `follow(clock)`: what makes the clock follow its
        node's /clock once jump callbacks are asked of it (the node's TimeSource)."""
        super().__init__(clock_type=ClockType.ROS_TIME)
        self._source = source
        self._follow = follow
        self._active: bool | None = None  # None: as the source says
        self._set_ns: int | None = None
        self._time_source: Any = None

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the time comes from /clock (use_sim_time)."""
        if self._active is not None:
            return self._active
        return bool(self._source is not None and self._source.use_sim_time)

    def _now_ns(self) -> int:
        if self._source is not None:
            return self._source.now().nanoseconds
        if self.ros_time_is_active:
            return self._set_ns or 0
        return _time.time_ns()

    def set_ros_time_is_active(self, active: bool) -> None:
        """Turn ROS time on or off (a TimeSource does, from use_sim_time): a clock change for
        the jump callbacks."""
        if active == self.ros_time_is_active:
            return
        before = self._now_ns()
        change = ClockChange.ROS_TIME_ACTIVATED if active else ClockChange.ROS_TIME_DEACTIVATED

        def switch() -> None:
            self._active = active
        after = (self._set_ns or 0) if active and self._source is None else \
            _time.time_ns() if self._source is None else before
        jump(self.jump_handles, change, after - before, switch)

    def set_ros_time(self, nanoseconds: int) -> None:
        """The ROS time is now `nanoseconds` (a TimeSource's /clock): a jump for the jump
        callbacks when ROS time is active."""
        before = self._set_ns if self._set_ns is not None else self._now_ns()

        def move() -> None:
            self._set_ns = nanoseconds
        if self.ros_time_is_active:
            jump(self.jump_handles, ClockChange.ROS_TIME_NO_CHANGE, nanoseconds - before, move)
        else:
            move()

    def create_jump_callback(self, threshold: JumpThreshold, *,
                             pre_callback: Callable[[], None] | None = None,
                             post_callback: Callable[[TimeJump], None] | None = None
                             ) -> JumpHandle:
        """As Clock's; a node's clock starts following its /clock for them."""
        handle = super().create_jump_callback(threshold, pre_callback=pre_callback,
                                              post_callback=post_callback)
        if self._follow is not None and self._time_source is None:
            self._time_source = self._follow(self)
        return handle
