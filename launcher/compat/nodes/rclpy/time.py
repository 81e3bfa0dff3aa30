"""rclpy.time.Time."""

from __future__ import annotations

import functools
from typing import Any

from rclpy.clock_type import ClockType
from rclpy.constants import S_TO_NS  # noqa: F401 - as rclpy's module offers it
from rclpy.duration import Duration
from rclpy.properties import readonly

_S = 1_000_000_000


@functools.total_ordering
class Time:
    __slots__ = ("_nanoseconds", "_clock_type")

    def __init__(self, *, seconds: float = 0, nanoseconds: int = 0,
                 clock_type: ClockType = ClockType.SYSTEM_TIME) -> None:
        if seconds < 0:
            raise ValueError("Seconds value must not be negative")
        if nanoseconds < 0:
            raise ValueError("Nanoseconds value must not be negative")
        total = int(seconds * _S) + int(nanoseconds)
        if total >= 2**63:
            raise OverflowError("Total nanoseconds value is too large to store in C time point.")
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        self._nanoseconds, self._clock_type = total, clock_type

    nanoseconds = readonly("_nanoseconds", "The time in nanoseconds.")
    clock_type = readonly("_clock_type", "The ClockType the time is of.")

    def seconds_nanoseconds(self) -> tuple[int, int]:
        """(seconds, nanoseconds past them)."""
        return divmod(self._nanoseconds, _S)

    def __repr__(self) -> str:
        return f"Time(nanoseconds={self._nanoseconds}, clock_type={self._clock_type.name})"

    def __str__(self) -> str:
        return f"{self._nanoseconds} nanoseconds"

    def __add__(self, other: Any) -> Time:
        if isinstance(other, Duration):
            return Time(nanoseconds=self._nanoseconds + other.nanoseconds,
                        clock_type=self._clock_type)
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, Time):
            if other._clock_type != self._clock_type:
                raise TypeError("Can't subtract times with different clock types")
            return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)
        if isinstance(other, Duration):
            return Time(nanoseconds=self._nanoseconds - other.nanoseconds,
                        clock_type=self._clock_type)
        return NotImplemented

    def _compare(self, other: Any) -> int:
        if not isinstance(other, Time):
            raise TypeError("Can't compare time with object of type: ", type(other))
        if other._clock_type != self._clock_type:
            raise TypeError("Can't compare times with different clock types")
        return self._nanoseconds - other._nanoseconds

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        return self._compare(other) == 0

    def __lt__(self, other: Time) -> bool:
        return self._compare(other) < 0

    def __hash__(self) -> int:
        return hash((self._nanoseconds, self._clock_type))

    def to_msg(self) -> Any:
        """The time as a builtin_interfaces/Time message."""
        from builtin_interfaces.msg import Time as Message

        sec, nanosec = self.seconds_nanoseconds()
        return Message(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, message: Any, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        """A Time from a builtin_interfaces/Time message."""
        return cls(seconds=message.sec, nanoseconds=message.nanosec, clock_type=clock_type)
