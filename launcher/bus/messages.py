"""Messages from plain data and back: `topic pub` YAML in, `topic echo` YAML out.

Missing fields take their definition's default values, else their zero values. A value that
does not fit names the field path and the type it expected (`linear.x: expected float64, got
'fast'`).
"""

from __future__ import annotations

import array
from types import SimpleNamespace
from typing import Any

from launcher.bus import kinds
from launcher.bus.types import registry
from launcher.errors import LaunchError, did_you_mean

# Integer ranges, and the numpy dtypes of primitive arrays (numpy is imported only when a
# message has such an array: node start-up time is benchmarked).
_INTS = {"byte": (0, 255), "char": (0, 255), "int8": (-2**7, 2**7 - 1), "uint8": (0, 255),
         "int16": (-2**15, 2**15 - 1), "uint16": (0, 2**16 - 1),
         "int32": (-2**31, 2**31 - 1), "uint32": (0, 2**32 - 1),
         "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1)}
_FLOATS = ("float32", "float64")
_DTYPES = {"byte": "uint8", "char": "uint8", "bool": "bool"}


class MessageError(LaunchError):
    pass


def build(type_name: str, values: Any, path: str = "", plain: bool = False) -> Any:
    """The message of `values` (a map of fields): the type's class, numeric arrays as numpy
    arrays; `plain`: objects with the fields and lists (no classes, no numpy), which
    serialise the same."""
    types = registry()
    name = types.ensure(type_name)
    if values is None:
        values = {}
    if getattr(values, "__msgtype__", None) == name:  # a message already (a stamp's to_msg())
        values = to_data(values)
    if not isinstance(values, dict):
        raise MessageError(f"{path or name}: expected a map of fields for {name}, "
                           f"got {values!r}")
    fields = types.fields(name)
    known = [f for f, _ in fields]
    for key in values:
        if key not in known:
            raise MessageError(f"{path}{key}: {name} has no field '{key}'"
                               f"{did_you_mean(str(key), known)}; fields: {', '.join(known)}")
    defaults = types.defaults(name)
    kwargs = {f: _value(kind, detail, values[f] if f in values else defaults.get(f),
                        f"{path}{f}", plain)
              for f, (kind, detail) in fields}
    return SimpleNamespace(**kwargs) if plain else types.message_class(name)(**kwargs)


def _value(kind: int, detail: Any, value: Any, path: str, plain: bool) -> Any:
    if kind == kinds.BASE:
        return _primitive(detail[0], value, path)
    if kind == kinds.NAME:
        return build(detail, value, f"{path}.", plain)
    (inner_kind, inner_detail), count = detail
    items = [] if value is None else value
    if not isinstance(items, list | tuple | array.array) and \
            type(items).__name__ != "ndarray":
        raise MessageError(f"{path}: expected a list, got {value!r}")
    if kind == kinds.ARRAY and value is None:
        items = [None] * count
    if kind == kinds.ARRAY and len(items) != count:
        raise MessageError(f"{path}: expected {count} items, got {len(items)}")
    converted = [_value(inner_kind, inner_detail, item, f"{path}[{i}]", plain)
                 for i, item in enumerate(items)]
    if not plain and inner_kind == kinds.BASE and inner_detail[0] not in ("string", "wstring"):
        import numpy as np  # rosbags wants primitive arrays as numpy arrays

        return np.array(converted, dtype=_DTYPES.get(inner_detail[0], inner_detail[0]))
    return converted


def _primitive(kind: str, value: Any, path: str) -> Any:
    if kind in ("string", "wstring"):
        if value is None:
            return ""
        if not isinstance(value, str | int | float | bool):
            raise MessageError(f"{path}: expected string, got {value!r}")
        return str(value)
    if kind == "bool":
        if value is None:
            return False
        if not isinstance(value, bool):
            raise MessageError(f"{path}: expected bool, got {value!r}")
        return value
    if value is None:
        return 0.0 if kind in _FLOATS else 0
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise MessageError(f"{path}: expected {kind}, got {value!r}")
    if kind in _FLOATS:
        return float(value)
    if not float(value).is_integer():
        raise MessageError(f"{path}: expected {kind} (a whole number), got {value!r}")
    low, high = _INTS[kind]
    if not low <= value <= high:
        raise MessageError(f"{path}: {value} is out of range for {kind}")
    return int(value)


def to_data(message: Any) -> Any:
    """Plain data (dicts, lists, numbers, strings) for YAML or CSV."""
    if hasattr(message, "tolist"):  # numpy arrays and scalars
        return message.tolist()
    if isinstance(message, list | tuple):
        return [to_data(m) for m in message]
    fields = getattr(message, "__dataclass_fields__", None)
    if fields is None:
        return message
    return {name: to_data(getattr(message, name)) for name in fields if name != "__msgtype__"}


# IDL's names for the primitives, as `ros2 topic echo --no-arr` writes an array's type
_IDL = {"float64": "double", "float32": "float", "bool": "boolean", "byte": "octet",
        "char": "uint8"}


def echo_data(message: Any, type_name: str, *, limit: int | None = 128, no_arr: bool = False,
              no_str: bool = False) -> Any:
    """A message as `ros2 topic echo` prints it: strings and arrays cut to `limit` items
    (with '...'), `no_arr` arrays as '<sequence type: double, length: 3>', `no_str` strings as
    '<string length: <5>>'."""
    types = registry()
    name = types.ensure(type_name)
    out = {}
    for field, (kind, detail) in types.fields(name):
        out[field] = _echo_value(getattr(message, field), kind, detail, limit, no_arr, no_str)
    return out


def _echo_value(value: Any, kind: int, detail: Any, limit: int | None, no_arr: bool,
                no_str: bool) -> Any:
    if kind == kinds.NAME:
        return echo_data(value, detail, limit=limit, no_arr=no_arr, no_str=no_str)
    if kind == kinds.BASE:
        value = to_data(value)
        if isinstance(value, str):
            if no_str:
                return f"<string length: <{len(value)}>>"
            if limit is not None and len(value) > limit:
                return value[:limit] + "..."
        return value
    (inner_kind, inner_detail), count = detail
    items = value.tolist() if hasattr(value, "tolist") else list(value)
    if no_arr:
        inner = inner_detail if inner_kind == kinds.NAME else \
            _IDL.get(inner_detail[0], inner_detail[0]) if inner_kind == kinds.BASE else "unknown"
        if kind == kinds.ARRAY:
            return f"<array type: {inner}[{count}]>"
        if count:
            return f"<sequence type: {inner}[{count}], length: {len(items)}>"
        return f"<sequence type: {inner}, length: {len(items)}>"
    cut = limit is not None and len(items) > limit
    shown = [_echo_value(item, inner_kind, inner_detail, limit, no_arr, no_str)
             for item in (items[:limit] if cut else items)]
    return [*shown, "..."] if cut else shown


_ARRAY_CODES = {"float64": "d", "float32": "f", "int8": "b", "uint8": "B", "int16": "h",
                "uint16": "H", "int32": "i", "uint32": "I", "int64": "q", "uint64": "Q"}


def ros_repr(message: Any) -> str:
    """A message as rclpy prints it: `geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(
    x=0.5, y=0.0, z=0.0), …)`, `std_msgs.msg.Empty()`, numbers' sequences as `array('d', […])`."""
    if hasattr(message, "dtype") and hasattr(message, "tolist"):  # a numpy sequence
        code = _ARRAY_CODES.get(str(message.dtype))
        values = message.tolist()
        return f"array('{code}', {values!r})" if code else repr(values)
    if isinstance(message, list | tuple):
        return "[" + ", ".join(ros_repr(m) for m in message) + "]"
    fields = getattr(message, "__dataclass_fields__", None)
    type_name = getattr(message, "__msgtype__", None)
    if fields is None or type_name is None:
        return repr(message)
    shown = [f"{name}={ros_repr(getattr(message, name))}" for name in fields
             if name not in ("__msgtype__", "structure_needs_at_least_one_member")]
    return f"{type_name.replace('/', '.')}({', '.join(shown)})"
