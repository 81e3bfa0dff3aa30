"""rclpy.type_hash: a type's RIHS hash (version and 32 bytes)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypedDict

from rclpy.properties import stored

_TYPE_HASH_SIZE = 32


def _checked(kind: type, message: str) -> Callable[[Any], Any]:
    """The value itself, or TypeError(message) when it is not a `kind`."""
    def check(value: Any) -> Any:
        if not isinstance(value, kind):
            raise TypeError(message)
        return value
    return check


class TypeHashDictionary(TypedDict):
    version: int
    value: bytes


class TypeHash:
    """A type description's hash: `RIHS01_<hex>` when printed."""

    __slots__ = ("_version", "_value")

    def __init__(self, version: int = -1, value: bytes = bytes(_TYPE_HASH_SIZE)) -> None:
        self.version, self.value = version, value

    version = stored("_version", "The hashing scheme's version (1 for RIHS01; -1 when unset).",
                     _checked(int, "version must be an int"))
    value = stored("_value", "The hash's bytes.", _checked(bytes, "value must be bytes"))

    @classmethod
    def from_text(cls, text: str) -> TypeHash:
        """The hash of its text form (`RIHS01_<64 hex digits>`; unset when it is not one)."""
        prefix, _, digits = text.partition("_")
        if not prefix.startswith("RIHS") or len(digits) != 2 * _TYPE_HASH_SIZE:
            return cls()
        return cls(int(prefix[4:]), bytes.fromhex(digits))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, TypeHash) and (self.version, self.value) == \
            (other.version, other.value)

    __hash__ = None  # type: ignore[assignment] - mutable, as rclpy's

    def __str__(self) -> str:
        if self._version <= 0 or len(self._value) != _TYPE_HASH_SIZE:
            return "INVALID"
        return f"RIHS{self._version:02}_{self._value.hex()}"
