"""rospy's Time and Duration. A Time is a `builtin_interfaces/Time` message too, so
`msg.header.stamp = rospy.Time.now()` works as in ROS 1; it answers to `secs`/`nsecs`
(ROS 1) and `sec`/`nanosec` (ROS 2)."""

from __future__ import annotations

import threading
import time as _time
from typing import Any

from launcher.compat import rosidl

_S = 1_000_000_000
_TimeMessage: Any = rosidl.message_class("builtin_interfaces/msg/Time")
_DurationMessage: Any = rosidl.message_class("builtin_interfaces/msg/Duration")


def _split(secs: Any, nsecs: int) -> tuple[int, int]:
    total = int(round(secs * _S)) + int(nsecs) if isinstance(secs, float) else \
        int(secs) * _S + int(nsecs)
    return divmod(total, _S)


class _Arithmetic:
    __slots__ = ()

    def to_nsec(self) -> int:
        return self.sec * _S + self.nanosec  # type: ignore[attr-defined]

    def to_sec(self) -> float:
        return self.to_nsec() / 1e9

    def is_zero(self) -> bool:
        return self.to_nsec() == 0

    def __lt__(self, other: Any) -> bool:
        return self.to_nsec() < other.to_nsec()

    def __le__(self, other: Any) -> bool:
        return self.to_nsec() <= other.to_nsec()

    def __gt__(self, other: Any) -> bool:
        return self.to_nsec() > other.to_nsec()

    def __ge__(self, other: Any) -> bool:
        return self.to_nsec() >= other.to_nsec()

    def __eq__(self, other: Any) -> bool:
        return hasattr(other, "to_nsec") and self.to_nsec() == other.to_nsec()

    def __hash__(self) -> int:
        return hash(self.to_nsec())

    def __bool__(self) -> bool:
        return not self.is_zero()


class Duration(_Arithmetic, _DurationMessage):
    __slots__ = ()

    def __init__(self, secs: Any = 0, nsecs: int = 0) -> None:
        seconds, nanos = _split(secs, nsecs)
        _DurationMessage.__init__(self, sec=seconds, nanosec=nanos)

    @property
    def secs(self) -> int:
        """Whole seconds."""
        return self.sec

    @property
    def nsecs(self) -> int:
        """Nanoseconds past the whole seconds."""
        return self.nanosec

    @classmethod
    def from_sec(cls, seconds: float) -> Duration:
        """A Duration of `float_secs` seconds."""
        return cls(float(seconds))

    def __add__(self, other: Any) -> Any:
        if isinstance(other, Time):
            return other + self
        if isinstance(other, Duration):
            return Duration(0, self.to_nsec() + other.to_nsec())
        return NotImplemented

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, Duration):
            return Duration(0, self.to_nsec() - other.to_nsec())
        return NotImplemented

    def __neg__(self) -> Duration:
        return Duration(0, -self.to_nsec())

    def __mul__(self, factor: float) -> Duration:
        return Duration(0, int(self.to_nsec() * factor))

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> Any:
        if isinstance(other, Duration):
            return self.to_nsec() / other.to_nsec()
        return Duration(0, int(self.to_nsec() / other))

    def __repr__(self) -> str:
        return f"rospy.Duration[{self.to_nsec()}]"


class Time(_Arithmetic, _TimeMessage):
    __slots__ = ()

    def __init__(self, secs: Any = 0, nsecs: int = 0) -> None:
        seconds, nanos = _split(secs, nsecs)
        if seconds < 0:
            raise TypeError("time values must be positive")
        _TimeMessage.__init__(self, sec=seconds, nanosec=nanos)

    @classmethod
    def from_sec(cls, seconds: float) -> Time:
        """A Time of `float_secs` seconds."""
        return cls(float(seconds))

    from_seconds = from_sec

    @classmethod
    def now(cls) -> Time:
        """The node's current time (sim time when use_sim_time is set)."""
        return get_rostime()

    def __add__(self, other: Any) -> Any:
        if isinstance(other, Duration):
            return Time(0, self.to_nsec() + other.to_nsec())
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, Time):
            return Duration(0, self.to_nsec() - other.to_nsec())
        if isinstance(other, Duration):
            return Time(0, self.to_nsec() - other.to_nsec())
        return NotImplemented

    def __repr__(self) -> str:
        return f"rospy.Time[{self.to_nsec()}]"


_initialized = [False]
_wallclock = [False]  # switch_to_wallclock: sim time no longer followed
_cond = threading.Condition()


def get_rostime() -> Time:
    """The node's current time as a Time (sim time when use_sim_time is set)."""
    from rospy.core import need_node

    node = need_node("time is not initialized")
    if _wallclock[0]:
        return Time(0, _time.time_ns())
    return Time(0, node.get_clock().now().nanoseconds)


def get_time() -> float:
    """The node's current time in seconds."""
    return get_rostime().to_sec()


def set_rostime_initialized(val: bool) -> None:
    """Mark the node's time as ready (init_node does) and wake those waiting on it."""
    with _cond:
        _initialized[0] = val
        _cond.notify_all()


def is_rostime_initialized() -> bool:
    """Whether the node's time is ready."""
    return _initialized[0]


def get_rostime_cond() -> threading.Condition:
    """The condition notified when the node's time becomes ready."""
    return _cond


def is_wallclock() -> bool:
    """Whether the node's time is the wall clock (not sim time)."""
    from rospy.core import state

    clock = state.node.get_clock() if state.node is not None else None
    return _wallclock[0] or not getattr(clock, "use_sim_time", False)


def switch_to_wallclock() -> None:
    """Use the wall clock from now on, even where use_sim_time is set."""
    _wallclock[0] = True


def wallsleep(duration: Any) -> None:
    """Sleep `duration` (seconds or a Duration) of wall time, whatever the node's clock."""
    seconds = duration.to_sec() if hasattr(duration, "to_sec") else float(duration)
    if seconds > 0:
        _time.sleep(seconds)
