"""rclpy.type_hash: a type's RIHS hash (version and 32 bytes)."""

from __future__ import annotations

from typing import TypedDict

_TYPE_HASH_SIZE = 32


class TypeHashDictionary(TypedDict):
    version: int
    value: bytes


class TypeHash:
    """A type description's hash: `RIHS01_<hex>` when printed."""

    __slots__ = ("_version", "_value")

    def __init__(self, version: int = -1, value: bytes = bytes(_TYPE_HASH_SIZE)) -> None:
        self.version, self.value = version, value

    @property
    def version(self) -> int:
        """The hashing scheme's version (1 for RIHS01; -1 when unset)."""
        return self._version

    @version.setter
    def version(self, value: int) -> None:
        if not isinstance(value, int):
            raise TypeError("version must be an int")
        self._version = value

    @property
    def value(self) -> bytes:
        """The hash's bytes."""
        return self._value

    @value.setter
    def value(self, value: bytes) -> None:
        if not isinstance(value, bytes):
            raise TypeError("value must be bytes")
        self._value = value

    @classmethod
    def from_text(cls, text: str) -> TypeHash:
        """The hash of its text form (`RIHS01_<64 hex digits>`; unset when it is not one)."""
        prefix, _, digits = text.partition("_")
        if not prefix.startswith("RIHS") or len(digits) != 2 * _TYPE_HASH_SIZE:
            return cls()
        return cls(int(prefix[4:]), bytes.fromhex(digits))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, TypeHash) and (self._version, self._value) == \
            (other._version, other._value)

    __hash__ = None  # type: ignore[assignment] - mutable, as rclpy's

    def __str__(self) -> str:
        if self._version <= 0 or len(self._value) != _TYPE_HASH_SIZE:
            return "INVALID"
        return f"RIHS{self._version:02}_{self._value.hex()}"
