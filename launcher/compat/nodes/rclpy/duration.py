"""rclpy.duration.Duration."""

from __future__ import annotations

import functools
from typing import Any

from rclpy.constants import S_TO_NS  # noqa: F401 - as rclpy's module offers it
from rclpy.properties import readonly

_S = 1_000_000_000


@functools.total_ordering
class Duration:
    __slots__ = ("_nanoseconds",)

    def __init__(self, *, seconds: float = 0, nanoseconds: int = 0) -> None:
        total = int(seconds * _S) + int(nanoseconds)
        if not -2**63 <= total < 2**63:
            raise OverflowError("Total nanoseconds value is too large to store in C duration.")
        self._nanoseconds = total

    nanoseconds = readonly("_nanoseconds", "The duration in nanoseconds.")

    def __repr__(self) -> str:
        return f"Duration(nanoseconds={self._nanoseconds})"

    def __str__(self) -> str:
        return f"{self._nanoseconds} nanoseconds"

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds == other._nanoseconds
        return NotImplemented

    def __lt__(self, other: Duration) -> bool:
        if not isinstance(other, Duration):
            raise TypeError("Can't compare duration with object of type: ", type(other))
        return self._nanoseconds < other._nanoseconds

    def __hash__(self) -> int:
        return hash(self._nanoseconds)

    def __add__(self, other: Any) -> Any:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._nanoseconds + other._nanoseconds)
        return NotImplemented

    def __sub__(self, other: Any) -> Any:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)
        return NotImplemented

    def __mul__(self, factor: float) -> Duration:
        return Duration(nanoseconds=int(self._nanoseconds * factor))

    __rmul__ = __mul__

    def to_msg(self) -> Any:
        """The duration as a builtin_interfaces/Duration message."""
        from builtin_interfaces.msg import Duration as Message

        sec, nanosec = divmod(self._nanoseconds, _S)
        return Message(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, message: Any) -> Duration:
        """A Duration from a builtin_interfaces/Duration message."""
        return cls(seconds=message.sec, nanoseconds=message.nanosec)

    def get_c_duration(self) -> Duration:
        """The duration itself (rclpy hands its C object here)."""
        return self


Infinite = Duration(nanoseconds=2**63 - 1)
