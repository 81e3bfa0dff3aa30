"""The byte protocol between a launch and its supervisor on another host (over ssh's channel:
the supervisor's stdin and stdout).

The supervisor first writes one line, `launcher-remote <protocol> <launcher version>`; what
comes before it (an env-loader's or a login shell's chatter) is not the protocol's. Then
frames, both ways: a big-endian u32 length of what follows, a kind byte, the body.

  J  a UTF-8 JSON object whose "t" says what it is (hello, start, exited, …)
  O  a process's output: u32 id, u8 stream (1 stdout, 2 stderr), then the raw bytes

Output travels as raw bytes (no base64), at most 64 KiB a frame, so that a ping never waits
behind much; a frame over 16 MiB, an unknown kind or a body that is not what its kind says is
a `ProtocolError`: the link is broken, not the frame.
"""

from __future__ import annotations

import json
import struct
from typing import Any, NamedTuple

from launcher import __version__
from launcher.errors import LaunchError

PROTOCOL = 1
MAGIC = b"launcher-remote"
MAX_FRAME = 16 << 20  # bytes of kind + body
MAX_OUTPUT = 64 << 10  # bytes of output in one O frame
MAX_NOISE_LINE = 64 << 10  # a line before the magic one is cut here (an endless one)
STDOUT, STDERR = 1, 2

_HEADER = struct.Struct(">IB")  # length, kind
_LENGTH = struct.Struct(">I")
_OUTPUT = struct.Struct(">IB")  # id, stream
_JSON, _BYTES = ord("J"), ord("O")


class ProtocolError(LaunchError):
    """The other side sent what the protocol does not allow."""


class ProtocolMismatch(ProtocolError):
    """The other side speaks another version of the protocol."""

    def __init__(self, protocol: int, version: str) -> None:
        super().__init__(f"the other side speaks remote protocol {protocol} (launcher "
                         f"{version}); this one speaks {PROTOCOL} (launcher {__version__})")
        self.protocol, self.version = protocol, version


class Message(NamedTuple):
    body: dict[str, Any]


class Output(NamedTuple):
    ident: int
    stream: int
    data: bytes


def magic_line() -> bytes:
    return b"%s %d %s\n" % (MAGIC, PROTOCOL, __version__.encode())


def parse_magic(line: bytes) -> tuple[int, str] | None:
    """(protocol, launcher version) from a magic line; None for any other line."""
    words = line.strip().split()
    if len(words) != 3 or words[0] != MAGIC or not words[1].isdigit():
        return None
    return int(words[1]), words[2].decode(errors="replace")


def message(body: dict[str, Any]) -> bytes:
    """A J frame. (ASCII JSON: a command line's undecodable bytes travel as escapes.)"""
    data = json.dumps(body, separators=(",", ":")).encode()
    return _frame(_JSON, data)


def output(ident: int, stream: int, data: bytes) -> bytes:
    """O frames holding `data` (one per 64 KiB)."""
    head = _OUTPUT.pack(ident, stream)
    return b"".join(_frame(_BYTES, head + data[at:at + MAX_OUTPUT])
                    for at in range(0, len(data), MAX_OUTPUT))


def _frame(kind: int, body: bytes) -> bytes:
    if len(body) + 1 > MAX_FRAME:
        raise ProtocolError(f"a frame of {len(body) + 1} bytes; at most {MAX_FRAME} go in one")
    return _HEADER.pack(len(body) + 1, kind) + body


class Decoder:
    """Frames out of a byte stream cut anywhere. With `magic`, the lines before the magic
    one are skipped (kept in `noise`, for the caller to log), and `peer` is what the magic
    line says; another protocol raises ProtocolMismatch."""

    def __init__(self, magic: bool = False) -> None:
        self._buffer = bytearray()
        self._waiting_magic = magic
        self.noise: list[bytes] = []
        self.peer: tuple[int, str] | None = None

    def feed(self, data: bytes) -> list[Message | Output]:
        self._buffer += data
        if self._waiting_magic and not self._skip_to_magic():
            return []
        found: list[Message | Output] = []
        at = 0
        while len(self._buffer) - at >= _LENGTH.size:
            (length,) = _LENGTH.unpack_from(self._buffer, at)
            if not 1 <= length <= MAX_FRAME:  # (said at once, not 16 MiB later)
                raise ProtocolError(f"a frame of {length} bytes; frames are 1 to {MAX_FRAME}")
            end = at + _LENGTH.size + length
            if len(self._buffer) < end:
                break
            kind = self._buffer[at + _LENGTH.size]
            found.append(_decode(kind, bytes(self._buffer[at + _HEADER.size:end])))
            at = end
        del self._buffer[:at]
        return found

    def _skip_to_magic(self) -> bool:
        """Consume lines up to the magic one; True once it has been read."""
        while True:
            end = self._buffer.find(b"\n")
            if end < 0:
                if len(self._buffer) > MAX_NOISE_LINE:
                    self.noise.append(bytes(self._buffer))
                    self._buffer.clear()
                return False
            line = bytes(self._buffer[:end + 1])
            del self._buffer[:end + 1]
            peer = parse_magic(line)
            if peer is None:
                self.noise.append(line.rstrip(b"\r\n"))
                continue
            self.peer, self._waiting_magic = peer, False
            if peer[0] != PROTOCOL:
                raise ProtocolMismatch(*peer)
            return True


def _decode(kind: int, body: bytes) -> Message | Output:
    if kind == _JSON:
        try:
            value = json.loads(body)
        except (UnicodeDecodeError, ValueError) as exc:
            raise ProtocolError(f"a J frame that is not JSON: {exc}") from None
        if not isinstance(value, dict) or not isinstance(value.get("t"), str):
            raise ProtocolError(f"a J frame that is not an object with a \"t\" string: "
                                f"{body[:80]!r}")
        return Message(value)
    if kind == _BYTES:
        if len(body) < _OUTPUT.size:
            raise ProtocolError(f"an O frame of {len(body)} bytes; its head alone is "
                                f"{_OUTPUT.size}")
        ident, stream = _OUTPUT.unpack_from(body)
        data = body[_OUTPUT.size:]
        if stream not in (STDOUT, STDERR):
            raise ProtocolError(f"an O frame for stream {stream}; streams are 1 and 2")
        if len(data) > MAX_OUTPUT:
            raise ProtocolError(f"an O frame of {len(data)} bytes of output; at most "
                                f"{MAX_OUTPUT}")
        return Output(ident, stream, data)
    raise ProtocolError(f"a frame of unknown kind {bytes([kind])!r}; kinds are J and O")
