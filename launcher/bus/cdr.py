"""CDR (little-endian, XCDR1 as ROS 2 writes it) without code generation and without numpy.

rosbags generates a serializer per type on first use and its generated code imports numpy:
together ~0.1–0.2 s before a node's first message of each type. Here each type gets a small
plan of its fields, made once, and messages are written and read by walking it, with the
standard library's struct: consecutive fixed-size fields, nested messages of them included
(a Twist, a Pose, a header's stamp), are one run read and written by one precompiled struct per
start alignment, their values gathered by one attrgetter. Messages are any objects with the
fields as attributes (the node API's classes, launcher's rclpy classes); reading builds them
through a `make(type, values)` the caller gives, so each API gets its own classes without a
copy. Numeric arrays are read as `array.array`s; the caller turns them into what its classes
hold.

Types with `wstring` fields are refused (rosbags' CDR has no `wstring` either).
"""

from __future__ import annotations

import array
import operator
import struct
from collections.abc import Callable
from typing import Any

from launcher.bus import kinds

HEADER = b"\x00\x01\x00\x00"  # CDR, little-endian
_FORMATS = {"bool": "?", "byte": "B", "char": "B", "int8": "b", "uint8": "B",
            "int16": "h", "uint16": "H", "int32": "i", "uint32": "I", "int64": "q",
            "uint64": "Q", "float32": "f", "float64": "d"}
TYPECODES = {"byte": "B", "char": "B", "int8": "b", "uint8": "B", "int16": "h",
             "uint16": "H", "int32": "i", "uint32": "I", "int64": "q", "uint64": "Q",
             "float32": "f", "float64": "d"}
_KINDS = {"f": "f", "d": "f", "b": "i", "h": "i", "i": "i", "q": "i", "B": "u", "H": "u",
          "I": "u", "Q": "u", "?": "b"}
_U32 = struct.Struct("<I")

_WSTRING = "wstring fields are not supported (use string: UTF-8)"

# plan ops: (field, kind, detail)
PRIM, STRING, MSG, PRIMS, STRINGS, MSGS, RUN = range(7)


class Unsupported(Exception):
    """A type with a field this codec cannot write (wstring)."""


class CdrError(ValueError):
    pass


class Codec:
    def __init__(self, fields_of: Callable[[str], list[tuple[str, Any]]]) -> None:
        self._fields_of = fields_of
        self._plans: dict[str, list[tuple[str, int, Any]]] = {}
        self._ops: dict[str, list[tuple[str, int, Any]]] = {}
        self._leaves: dict[str, list[tuple[str, str]] | None] = {}

    def plan(self, name: str) -> list[tuple[str, int, Any]]:
        found = self._plans.get(name)
        if found is not None:
            return found
        ops: list[tuple[str, int, Any]] = []
        for field, (kind, detail) in self._fields_of(name):
            if kind == kinds.BASE:
                ops.append((field, *_base(detail[0])))
            elif kind == kinds.NAME:
                ops.append((field, MSG, detail))
            else:
                (inner_kind, inner_detail), count = detail
                fixed = count if kind == kinds.ARRAY else None
                if inner_kind == kinds.NAME:
                    ops.append((field, MSGS, (inner_detail, fixed)))
                elif inner_detail[0] in ("string", "wstring"):
                    if inner_detail[0] == "wstring":
                        raise Unsupported(_WSTRING)
                    ops.append((field, STRINGS, fixed))
                else:
                    base = inner_detail[0]
                    size = struct.calcsize(_FORMATS[base])
                    code = TYPECODES.get(base, "")
                    ops.append((field, PRIMS, (_FORMATS[base], size, fixed, code, base)))
        self._plans[name] = ops
        for _, kind, detail in ops:  # nested plans now: a wstring anywhere is found here
            if kind == MSG:
                self.plan(detail)
            elif kind == MSGS:
                self.plan(detail[0])
        return ops

    # --- runs of fixed-size fields --------------------------------------------------------
    def _fixed_leaves(self, name: str) -> list[tuple[str, str]] | None:
        """(dotted path, struct format) of every field of a type made of fixed-size
        primitives and messages of them only; None for any other type."""
        if name in self._leaves:
            return self._leaves[name]
        leaves: list[tuple[str, str]] | None = []
        for field, kind, detail in self.plan(name):
            inner = self._fixed_leaves(detail) if kind == MSG else None
            if kind == PRIM:
                leaves.append((field, detail[0]))
            elif inner is not None:
                leaves += [(f"{field}.{path}", fmt) for path, fmt in inner]
            else:
                leaves = None
                break
        self._leaves[name] = leaves
        return leaves

    def ops(self, name: str) -> list[tuple[str, int, Any]]:
        """The plan with each stretch of fixed-size fields made one RUN."""
        found = self._ops.get(name)
        if found is not None:
            return found
        ops: list[tuple[str, int, Any]] = []
        stretch: list[tuple[str, int, Any]] = []
        for op in self.plan(name):
            field, kind, detail = op
            if kind == PRIM or (kind == MSG and self._fixed_leaves(detail) is not None):
                stretch.append(op)
                continue
            if stretch:
                ops.append(("", RUN, _Run(self, stretch)))
                stretch = []
            ops.append(op)
        if stretch:
            ops.append(("", RUN, _Run(self, stretch)))
        self._ops[name] = ops
        return ops

    # --- writing ----------------------------------------------------------------------------
    def serialize(self, message: Any, name: str) -> bytes:
        out = bytearray(HEADER)
        try:
            self._write_fast(out, message, self.ops(name))
        except struct.error:  # written again field by field, to say which field
            out = bytearray(HEADER)
            self._write(out, message, self.plan(name))
        return bytes(out)

    def _write_fast(self, out: bytearray, message: Any, ops: list[tuple[str, int, Any]]
                    ) -> None:
        for field, kind, detail in ops:
            if kind == RUN:
                out += detail.structs[(len(out) - 4) % 8].pack(*detail.values(message))
            elif kind == MSG:
                self._write_fast(out, getattr(message, field), self.ops(detail))
            elif kind == MSGS:
                inner, fixed = detail
                value = getattr(message, field)
                _write_count(out, field, len(value), fixed)
                inner_ops = self.ops(inner)
                for item in value:
                    self._write_fast(out, item, inner_ops)
            else:
                self._write(out, message, ((field, kind, detail),))

    def _write(self, out: bytearray, message: Any, ops: Any) -> None:
        for field, kind, detail in ops:
            value = getattr(message, field)
            if kind == PRIM:
                fmt, size = detail
                pad = -(len(out) - 4) % size
                if pad:
                    out += b"\x00" * pad
                try:
                    out += struct.pack("<" + fmt, value)
                except struct.error as exc:
                    raise CdrError(f"{field}: {exc} ({value!r})") from None
            elif kind == STRING:
                self._string(out, value)
            elif kind == MSG:
                self._write(out, value, self.plan(detail))
            elif kind == PRIMS:
                fmt, size, fixed, code, _ = detail
                count = _write_count(out, field, len(value), fixed)
                if count:
                    _align(out, size)
                    out += _packed(value, fmt, size, code, count)
            elif kind == STRINGS:
                _write_count(out, field, len(value), detail)
                for item in value:
                    self._string(out, item)
            else:  # MSGS
                inner, fixed = detail
                _write_count(out, field, len(value), fixed)
                inner_ops = self.plan(inner)
                for item in value:
                    self._write(out, item, inner_ops)

    @staticmethod
    def _string(out: bytearray, value: str) -> None:
        data = value.encode()
        _align(out, 4)
        out += _U32.pack(len(data) + 1)
        out += data
        out += b"\x00"

    # --- reading ----------------------------------------------------------------------------
    def deserialize(self, data: bytes | memoryview, name: str,
                    make: Callable[[str, list[Any]], Any]) -> Any:
        view = memoryview(data)
        if len(view) < 4:
            raise CdrError("a CDR payload needs at least its 4-byte header")
        if view[1] != 1:
            raise CdrError("only little-endian CDR is read here")
        message, _ = self._read(view[4:], 0, name, make)
        return message

    def _read(self, view: memoryview, pos: int, name: str,
              make: Callable[[str, list[Any]], Any]) -> tuple[Any, int]:
        values: list[Any] = []
        try:
            for _field, kind, detail in self.ops(name):
                if kind == RUN:
                    structure = detail.structs[pos % 8]
                    flat = structure.unpack_from(view, pos)
                    pos += structure.size
                    if detail.shape is None:
                        values += flat
                    else:
                        _rebuild(detail.shape, flat, 0, make, values)
                elif kind == PRIM:
                    fmt, size = detail
                    pos += -pos % size
                    values.append(struct.unpack_from("<" + fmt, view, pos)[0])
                    pos += size
                elif kind == STRING:
                    text, pos = _read_string(view, pos)
                    values.append(text)
                elif kind == MSG:
                    item, pos = self._read(view, pos, detail, make)
                    values.append(item)
                elif kind == PRIMS:
                    fmt, size, fixed, code, base = detail
                    count, pos = _read_count(view, pos, fixed)
                    if count:
                        pos += -pos % size
                    end = pos + count * size
                    if end > len(view):
                        raise CdrError("the payload ends inside an array")
                    if base == "bool":
                        values.append(list(struct.unpack_from(f"<{count}?", view, pos)))
                    else:
                        items = array.array(code)
                        items.frombytes(view[pos:end])
                        values.append(items)
                    pos = end
                elif kind == STRINGS:
                    count, pos = _read_count(view, pos, detail)
                    _check_count(count, view, pos)
                    items = []
                    for _ in range(count):
                        text, pos = _read_string(view, pos)
                        items.append(text)
                    values.append(items)
                else:  # MSGS
                    inner, fixed = detail
                    count, pos = _read_count(view, pos, fixed)
                    _check_count(count, view, pos)
                    items = []
                    for _ in range(count):
                        item, pos = self._read(view, pos, inner, make)
                        items.append(item)
                    values.append(items)
        except struct.error:
            raise CdrError(f"the payload ends inside a {name}") from None
        return make(name, values), pos


class _Run:
    """Consecutive fixed-size fields of a message: their values gathered by one attrgetter,
    written and read by one struct per start alignment (CDR aligns each primitive to its size,
    at most 8, from the start of the payload after its header), and on reading rebuilt into
    the nested messages they came from (`shape`; None when they are all primitives)."""

    def __init__(self, codec: Codec, ops: list[tuple[str, int, Any]]) -> None:
        leaves: list[tuple[str, str]] = []
        self.shape: list[Any] | None = None
        for field, kind, detail in ops:
            if kind == PRIM:
                leaves.append((field, detail[0]))
            else:
                inner = codec._fixed_leaves(detail) or []
                leaves += [(f"{field}.{path}", fmt) for path, fmt in inner]
                self.shape = []
        if self.shape is not None:
            self.shape = [_shape(codec, kind, detail) for _field, kind, detail in ops]
        getter = operator.attrgetter(*(path for path, _ in leaves))
        self.values = getter if len(leaves) > 1 else lambda message: (getter(message),)
        self.structs = [_aligned([fmt for _, fmt in leaves], start) for start in range(8)]


def _shape(codec: Codec, kind: int, detail: Any) -> Any:
    """None for a primitive; (type, [shapes of its fields]) for a nested message."""
    if kind == PRIM:
        return None
    return detail, [_shape(codec, k, d) for _f, k, d in codec.plan(detail)]


def _rebuild(shape: list[Any], flat: tuple[Any, ...], index: int,
             make: Callable[[str, list[Any]], Any], values: list[Any]) -> int:
    """Append the values of `shape`'s fields, nested messages made, from flat[index:]; the
    index after them."""
    for item in shape:
        if item is None:
            values.append(flat[index])
            index += 1
        else:
            inner: list[Any] = []
            index = _rebuild(item[1], flat, index, make, inner)
            values.append(make(item[0], inner))
    return index


def _aligned(formats: list[str], start: int) -> struct.Struct:
    """One struct for primitives written from a position `start` (mod 8), with CDR's padding."""
    text, position = ["<"], start
    for fmt in formats:
        size = struct.calcsize(fmt)
        pad = -position % size
        text.append("x" * pad + fmt)
        position += pad + size
    return struct.Struct("".join(text))


def _base(kind: str) -> tuple[int, Any]:
    if kind == "string":
        return STRING, None
    if kind == "wstring":
        raise Unsupported(_WSTRING)
    fmt = _FORMATS[kind]
    return PRIM, (fmt, struct.calcsize(fmt))


def _align(out: bytearray, size: int) -> None:
    pad = -(len(out) - 4) % size
    if pad:
        out += b"\x00" * pad


def _write_count(out: bytearray, field: str, count: int, fixed: int | None) -> int:
    """A sequence's count (aligned), or the check of a fixed array's length."""
    if fixed is None:
        _align(out, 4)
        out += _U32.pack(count)
    elif count != fixed:
        raise CdrError(f"{field}: expected {fixed} items, got {count}")
    return count


def _read_count(view: memoryview, pos: int, fixed: int | None) -> tuple[int, int]:
    """(count, position after it): a sequence's count, or a fixed array's length."""
    if fixed is not None:
        return fixed, pos
    pos += -pos % 4
    return _U32.unpack_from(view, pos)[0], pos + 4


def _packed(value: Any, fmt: str, size: int, code: str, count: int) -> bytes:
    """A numeric array's bytes: straight from an array.array or numpy array of the type, or
    from bytes for a byte array (an image's data)."""
    if isinstance(value, array.array) and value.typecode == code:
        return value.tobytes()
    if size == 1 and isinstance(value, bytes | bytearray | memoryview):
        return bytes(value)
    dtype = getattr(value, "dtype", None)  # a numpy array, read without importing numpy
    if dtype is not None and dtype.itemsize == size and dtype.kind == _KINDS[fmt] \
            and dtype.byteorder in "=<|":
        return value.tobytes()
    try:
        return struct.pack(f"<{count}{fmt}", *(v.item() if hasattr(v, "item") else v
                                               for v in value))
    except struct.error as exc:
        raise CdrError(f"{exc}") from None


def _read_string(view: memoryview, pos: int) -> tuple[str, int]:
    pos += -pos % 4
    length = _U32.unpack_from(view, pos)[0]
    pos += 4
    if pos + length > len(view):
        raise CdrError("the payload ends inside a string")
    end = pos + length - 1 if length else pos
    return bytes(view[pos:end]).decode(errors="replace"), pos + length


def _check_count(count: int, view: memoryview, pos: int) -> None:
    """A sequence cannot have more items than bytes left (a hostile count allocates nothing)."""
    if count > len(view) - pos:
        raise CdrError(f"a sequence of {count} items in {len(view) - pos} bytes")
