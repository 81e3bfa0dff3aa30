"""CDR on the wire, packed and read directly where a message goes out at every step or
every joint_states message: the sim's clock, robot_state_publisher's /tf, and the joint states
it reads. Every layout here is tested byte for byte against rosbags' serializer, which is the
general path for everything else (bus/types.py).

Payloads are little-endian CDR: a 4-byte header, then fields aligned to their size counted
from the end of the header.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence
from typing import Any

CDR_HEADER = b"\x00\x01\x00\x00"  # CDR, little-endian
_STAMP = struct.Struct("<iI")
_STAMP_WORDS = struct.Struct("<II")
_SEVEN = struct.Struct("<7d")
_COUNT = struct.Struct("<I")
_CLOCK = struct.Struct("<4siIiI?7xQ")
_ROS_CLOCK = struct.Struct("<4siI")


def split_time(seconds: float) -> tuple[int, int]:
    """Seconds as (sec, nanosec), rounded to the nearest nanosecond: a sim time summed from
    steps that falls a hair short of 10 s is 10 s, not 9.999999999."""
    return divmod(int(round(seconds * 1e9)), 1_000_000_000)


def fill_stamp(stamp: Any, seconds: float) -> None:
    """Set a builtin_interfaces Time or Duration (`sec`, `nanosec`) to `seconds`."""
    stamp.sec, stamp.nanosec = split_time(seconds)


def stamp_seconds(stamp: Any) -> float:
    """A builtin_interfaces Time or Duration (`sec`, `nanosec`) in seconds."""
    return stamp.sec + stamp.nanosec * 1e-9


def stamp_nanoseconds(stamp: Any) -> int:
    """A builtin_interfaces Time or Duration (`sec`, `nanosec`) in nanoseconds, exactly."""
    return stamp.sec * 1_000_000_000 + stamp.nanosec


def clock_cdr(sim: float, real: float, paused: bool, iterations: int) -> bytes:
    """mujoco_sim/msg/Clock as CDR, packed directly: it goes out after every step."""
    return _CLOCK.pack(CDR_HEADER, *split_time(sim), *split_time(real), paused, iterations)


def ros_clock_cdr(sim: float) -> bytes:
    """rosgraph_msgs/msg/Clock as CDR (a builtin_interfaces/Time)."""
    return _ROS_CLOCK.pack(CDR_HEADER, *split_time(sim))


def image_cdr(sec: int, nanosec: int, frame_id: str, height: int, width: int, encoding: str,
              step: int, data: Any) -> bytearray:
    """sensor_msgs/msg/Image (and the sim's Image, the same layout) as CDR, the pixels (a
    C-contiguous buffer of `height * step` bytes) copied once: a camera's frames are megabytes
    each, and the general serializer copies them several times."""
    size = len(memoryview(data).cast("B"))
    head = bytearray(CDR_HEADER)
    head += _STAMP.pack(sec, nanosec)
    head += _string(frame_id)
    head += b"\0" * (-(len(head) - 4) % 4)
    head += _COUNT.pack(height) + _COUNT.pack(width)
    head += _string(encoding)
    head += b"\0"  # is_bigendian
    head += b"\0" * (-(len(head) - 4) % 4)
    head += _COUNT.pack(step) + _COUNT.pack(size)
    return head + memoryview(data).cast("B")  # (one copy, none zero-filled first)


def _string(text: str) -> bytes:
    data = text.encode() + b"\0"
    return _COUNT.pack(len(data)) + data


class TfLayout:
    """A tf2_msgs/msg/TFMessage's CDR bytes for a fixed list of (parent, child) frames, with
    the places of its stamps and numbers: packing one is a copy and a few `pack_into`s.

    At 1 kHz with 20 joints this is the node's main cost; building message objects for a
    generic serializer costs several times more."""

    def __init__(self, parents: list[str], children: list[str]) -> None:
        out = bytearray(CDR_HEADER)
        out += _COUNT.pack(len(parents))
        self._places: list[tuple[int, int]] = []  # (stamp, numbers) of each transform
        for parent, child in zip(parents, children, strict=True):
            out += b"\0" * (-(len(out) - 4) % 4)
            stamp = len(out)
            out += bytes(8)
            out += _string(parent)
            out += b"\0" * (-(len(out) - 4) % 4)
            out += _string(child)
            out += b"\0" * (-(len(out) - 4) % 8)
            self._places.append((stamp, len(out)))
            out += bytes(56)
        self.template = bytes(out)

    def pack(self, sec: int, nanosec: int, translations: Sequence[Sequence[float]],
             quats: Sequence[Sequence[float]]) -> bytes:
        out = bytearray(self.template)
        sec &= 0xFFFFFFFF
        stamp, seven = _STAMP_WORDS.pack_into, _SEVEN.pack_into
        for (stamp_at, numbers_at), (x, y, z), (qx, qy, qz, qw) in zip(
                self._places, translations, quats, strict=True):
            stamp(out, stamp_at, sec, nanosec)
            seven(out, numbers_at, x, y, z, qx, qy, qz, qw)
        return bytes(out)


class JointStateLayout:
    """sensor_msgs/msg/JointState's CDR bytes for fixed names and frame: the stamp and the
    three arrays packed into a template (joint_state_broadcaster sends one every control
    cycle, at 1 kHz on an arm: the generic serializer cost more than the controllers)."""

    def __init__(self, names: list[str], frame_id: str = "") -> None:
        out = bytearray(CDR_HEADER) + bytes(8) + _string(frame_id)
        out += b"\0" * (-(len(out) - 4) % 4)
        out += _COUNT.pack(len(names))
        for name in names:
            out += b"\0" * (-(len(out) - 4) % 4)
            out += _string(name)
        self.count = len(names)
        self._doubles = struct.Struct(f"<{len(names)}d")
        self._places = []
        for _ in range(3):  # position, velocity, effort
            out += b"\0" * (-(len(out) - 4) % 4)
            out += _COUNT.pack(len(names))
            if names:
                out += b"\0" * (-(len(out) - 4) % 8)
            self._places.append(len(out))
            out += bytes(8 * len(names))
        self.template = bytes(out)

    def pack(self, sec: int, nanosec: int, position: Sequence[float],
             velocity: Sequence[float], effort: Sequence[float]) -> bytes:
        out = bytearray(self.template)
        _STAMP_WORDS.pack_into(out, 4, sec & 0xFFFFFFFF, nanosec)
        doubles = self._doubles.pack_into
        for place, values in zip(self._places, (position, velocity, effort), strict=True):
            doubles(out, place, *values)
        return bytes(out)


class JointStateReader:
    """Reads stamp, names and positions from sensor_msgs/msg/JointState CDR without building
    a message; the names, which rarely change, are decoded once and then only compared."""

    def __init__(self) -> None:
        self._block = b""
        self._names: list[str] = []

    def read(self, payload: bytes) -> tuple[int, int, list[str], Sequence[float]]:
        if payload[1] != 1:  # big-endian CDR: rare; let the generic reader do it
            from launcher.bus.types import registry

            message = registry().deserialize(payload, "sensor_msgs/msg/JointState")
            return (message.header.stamp.sec, message.header.stamp.nanosec, list(message.name),
                    [float(v) for v in message.position])
        data = memoryview(payload)[4:]
        sec, nanosec = _STAMP.unpack_from(data, 0)
        position = 12 + _COUNT.unpack_from(data, 8)[0]  # past frame_id
        position += -position % 4
        count = _COUNT.unpack_from(data, position)[0]
        start = position = position + 4
        block = self._block
        if count == len(self._names) and data[start:start + len(block)] == block:
            position = start + len(block)
            names = self._names
        else:
            names = []
            for _ in range(count):
                position += -position % 4
                size = _COUNT.unpack_from(data, position)[0]
                names.append(bytes(data[position + 4:position + 3 + size]).decode())
                position += 4 + size
            self._block, self._names = bytes(data[start:position]), names
        position += -position % 4
        values = _COUNT.unpack_from(data, position)[0]
        position += 4
        position += -position % 8
        return sec, nanosec, names, struct.unpack_from(f"<{values}d", data, position)


def pack_tf(sec: int, nanosec: int, parents: list[str], children: list[str],
            translations: Sequence[Sequence[float]], quats: Sequence[Sequence[float]]) -> bytes:
    """tf2_msgs/msg/TFMessage as CDR (see TfLayout)."""
    return TfLayout(parents, children).pack(sec, nanosec, translations, quats)
