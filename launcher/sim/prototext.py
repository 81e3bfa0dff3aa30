"""Protocol Buffers' text format, as `gz topic -p`, `gz service --req` and `gz topic -e` use it.

`parse` turns `linear: {x: 0.5}, angular {z: 0.2}` into nested dicts (a repeated field
becomes a list); `format` prints dicts the way Gazebo prints messages (nested blocks, zero
and empty fields left out). Both are independent of any message type: the gz message
modules check the fields.
"""

from __future__ import annotations

import math
import re
from typing import Any

from launcher.errors import UsageError

_TOKEN = re.compile(r"""
    (?P<space>\s+|\#[^\n]*)
  | (?P<string>"(?:\\.|[^"\\])*"|'(?:\\.|[^'\\])*')
  | (?P<number>[-+]?(?:\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)[fF]?)
  | (?P<word>[-+]?[A-Za-z_][\w.]*)
  | (?P<punct>[{}\[\]<>:,;])
""", re.X)
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", '"': '"', "'": "'", "\\": "\\"}
_CLOSE = {"{": "}", "<": ">"}


class TextFormatError(UsageError):
    pass


def parse(text: str, what: str = "the message") -> dict[str, Any]:
    tokens = _tokens(text, what)
    parser = _Parser(tokens, text, what)
    fields = parser.fields(end=None)
    return fields


def _tokens(text: str, what: str) -> list[tuple[str, str, int]]:
    found, position = [], 0
    while position < len(text):
        match = _TOKEN.match(text, position)
        if match is None:
            raise TextFormatError(f"{what}: unexpected '{text[position]}' at column "
                                  f"{position + 1} of: {text}")
        kind = match.lastgroup or ""
        if kind != "space":
            found.append((kind, match.group(), position))
        position = match.end()
    return found


class _Parser:
    def __init__(self, tokens: list[tuple[str, str, int]], text: str, what: str) -> None:
        self.tokens, self.text, self.what, self.index = tokens, text, what, 0

    def error(self, expected: str) -> TextFormatError:
        if self.index < len(self.tokens):
            _, value, column = self.tokens[self.index]
            return TextFormatError(f"{self.what}: expected {expected} at column {column + 1}, "
                                   f"found '{value}' in: {self.text}")
        return TextFormatError(f"{self.what}: expected {expected} at the end of: {self.text}")

    def peek(self) -> tuple[str, str] | None:
        if self.index < len(self.tokens):
            kind, value, _ = self.tokens[self.index]
            return kind, value
        return None

    def take(self) -> tuple[str, str]:
        token = self.peek()
        if token is None:
            raise self.error("more")
        self.index += 1
        return token

    def fields(self, end: str | None) -> dict[str, Any]:
        result: dict[str, Any] = {}
        while True:
            token = self.peek()
            if token is None:
                if end is not None:
                    raise self.error(f"'{end}'")
                return result
            if token == ("punct", end):
                self.index += 1
                return result
            if token[1] in (",", ";"):
                self.index += 1
                continue
            kind, name = self.take()
            if kind != "word":
                self.index -= 1
                raise self.error("a field name")
            value = self.field_value()
            if name in result:
                previous = result[name]
                result[name] = [*previous, value] if isinstance(previous, list) and \
                    not isinstance(value, list) else [previous, value]
            else:
                result[name] = value

    def field_value(self) -> Any:
        token = self.peek()
        if token == ("punct", ":"):
            self.index += 1
            token = self.peek()
        if token is not None and token[1] in _CLOSE:
            self.index += 1
            return self.fields(_CLOSE[token[1]])
        if token == ("punct", "["):
            self.index += 1
            return self.list_value()
        return self.scalar()

    def list_value(self) -> list[Any]:
        items: list[Any] = []
        while True:
            token = self.peek()
            if token == ("punct", "]"):
                self.index += 1
                return items
            if token == ("punct", ","):
                self.index += 1
                continue
            if token is not None and token[1] in _CLOSE:
                self.index += 1
                items.append(self.fields(_CLOSE[token[1]]))
            else:
                items.append(self.scalar())

    def scalar(self) -> Any:
        kind, value = self.take()
        if kind == "number":
            number = float(value.rstrip("fF"))
            return int(number) if re.fullmatch(r"[-+]?\d+", value) else number
        if kind == "string":
            parts = [_unquote(value)]
            while self.peek() is not None and self.peek()[0] == "string":  # type: ignore[index]
                parts.append(_unquote(self.take()[1]))
            return "".join(parts)
        if kind == "word":
            lowered = value.lower().lstrip("+")
            if lowered in ("true", "t"):
                return True
            if lowered in ("false", "f"):
                return False
            if lowered in ("inf", "infinity", "-inf", "-infinity", "nan"):
                return float(lowered)
            return Enum(value)
        self.index -= 1
        raise self.error("a value")


class Enum(str):
    """An enum value written by name (`type: MODEL`)."""


def _unquote(token: str) -> str:
    body = token[1:-1]
    return re.sub(r"\\(.)", lambda m: _ESCAPES.get(m.group(1), m.group(1)), body)


def format(data: dict[str, Any], indent: int = 0) -> str:  # noqa: A001 - the format's verb
    """`data` as Gazebo prints a message; zero and empty fields are left out."""
    lines: list[str] = []
    pad = "  " * indent
    for name, value in data.items():
        items = value if isinstance(value, list) else [value]
        for item in items:
            if isinstance(item, dict):
                inner = format(item, indent + 1)
                if inner:
                    lines.append(f"{pad}{name} {{\n{inner}{pad}}}\n")
            elif not _is_default(item):
                lines.append(f"{pad}{name}: {_scalar(item)}\n")
    return "".join(lines)


_BYTE_ESCAPES = [chr(b) if 0x20 <= b < 0x7f and b not in (0x22, 0x27, 0x5c) else
                 {0x0a: "\\n", 0x0d: "\\r", 0x09: "\\t", 0x22: '\\"', 0x27: "\\'",
                  0x5c: "\\\\"}.get(b, f"\\{b:03o}") for b in range(256)]


def _is_default(value: Any) -> bool:
    return value is None or value is False or value in ("", b"") or \
        (isinstance(value, int | float) and not isinstance(value, bool) and value == 0)


def _scalar(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, Enum):
        return str(value)
    if isinstance(value, bytes | bytearray):  # as protobuf writes bytes: C escapes
        return '"' + "".join(_BYTE_ESCAPES[b] for b in value) + '"'
    if isinstance(value, str):
        escaped = value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
        return f'"{escaped}"'
    if isinstance(value, float):
        return "inf" if value == math.inf else "-inf" if value == -math.inf else \
            "nan" if math.isnan(value) else repr(value)
    return str(value)
