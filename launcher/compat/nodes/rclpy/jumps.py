"""Time jumps of a clock, as rcl reports them: JumpThreshold says which jumps matter,
JumpHandle holds a pair of callbacks on a clock, TimeJump is what the post callback gets.

A ROS clock jumps when the time it follows (`/clock`, set by a TimeSource) moves by more than
a threshold, or when ROS time is activated or deactivated (ClockChange).
"""

from __future__ import annotations

from collections.abc import Callable
from enum import IntEnum
from typing import Any, TypedDict

from rclpy.duration import Duration
from rclpy.properties import readonly


class ClockChange(IntEnum):
    """How a jump changed the clock (rcl_clock_change_t)."""

    ROS_TIME_NO_CHANGE = 1
    ROS_TIME_ACTIVATED = 2
    ROS_TIME_DEACTIVATED = 3
    SYSTEM_TIME_NO_CHANGE = 4


class JumpThreshold:
    """Which jumps call back: forward by `min_forward` or more, backward by `min_backward`
    (a negative Duration) or more, and (`on_clock_change`) ROS time turned on or off."""

    def __init__(self, *, min_forward: Duration | None, min_backward: Duration | None,
                 on_clock_change: bool = True) -> None:
        if min_forward is not None and min_forward.nanoseconds <= 0:
            raise ValueError("min_forward must be a positive non-zero duration")
        if min_backward is not None and min_backward.nanoseconds >= 0:
            raise ValueError("min_backward must be a negative non-zero duration")
        if min_forward is None and min_backward is None and not on_clock_change:
            raise ValueError("At least one jump threshold must be enabled")
        self.min_forward = min_forward
        self.min_backward = min_backward
        self.on_clock_change = on_clock_change

    def exceeded_by(self, change: ClockChange, delta_ns: int) -> bool:
        """Whether a jump of `delta_ns` with `change` crosses this threshold."""
        if change in (ClockChange.ROS_TIME_ACTIVATED, ClockChange.ROS_TIME_DEACTIVATED):
            return self.on_clock_change
        return (self.min_forward is not None and delta_ns >= self.min_forward.nanoseconds) or \
            (self.min_backward is not None and delta_ns <= self.min_backward.nanoseconds)


class TimeJump:
    """A jump: how the clock changed, and by how much."""

    def __init__(self, clock_change: ClockChange, delta: Duration) -> None:
        if not isinstance(clock_change, ClockChange):
            raise TypeError("clock_change must be an instance of rclpy.clock.ClockChange")
        self._clock_change = clock_change
        self._delta = delta

    clock_change = readonly("_clock_change", "How the clock changed.")
    delta = readonly("_delta", "How far the time moved.")


class TimeJumpDictionary(TypedDict):
    """A jump as a JumpHandle's post callback gets it (delta in nanoseconds)."""

    clock_change: ClockChange
    delta: int


class JumpHandle:
    """Callbacks on `clock`, called before (`pre_callback()`) and after
    (`post_callback(TimeJumpDictionary)`) a jump that crosses `threshold`."""

    def __init__(self, *, clock: Any, threshold: JumpThreshold,
                 pre_callback: Callable[[], None] | None,
                 post_callback: Callable[[TimeJumpDictionary], None] | None) -> None:
        if pre_callback is None and post_callback is None:
            raise ValueError("One of pre_callback or post_callback must be True")
        self._clock = clock
        self.threshold = threshold
        self.pre_callback = pre_callback
        self.post_callback = post_callback
        clock.jump_handles.append(self)

    def unregister(self) -> None:
        """Stop calling back."""
        if self._clock is not None and self in self._clock.jump_handles:
            self._clock.jump_handles.remove(self)
        self._clock = None

    def __enter__(self) -> JumpHandle:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.unregister()


def jump(handles: list[JumpHandle], change: ClockChange, delta_ns: int,
         set_time: Callable[[], None]) -> None:
    """Move a clock: the pre callbacks of the handles the jump crosses, `set_time()`, then
    their post callbacks."""
    crossed = [handle for handle in handles if handle.threshold.exceeded_by(change, delta_ns)]
    for handle in crossed:
        if handle.pre_callback is not None:
            handle.pre_callback()
    set_time()
    for handle in crossed:
        if handle.post_callback is not None:
            handle.post_callback({"clock_change": change, "delta": delta_ns})
