"""Message and service classes with rclpy's Python semantics, made from launcher's type store.

`from geometry_msgs.msg import Twist` gives what rosidl_generator_py would have generated:
slots, a keyword constructor with defaults (positional arguments in field order too, as ROS 1
allowed), type-checked properties with rosidl's error texts, `__eq__`, `__repr__` as
`geometry_msgs.msg.Twist(linear=…)`, `get_fields_and_field_types()`, `SLOT_TYPES` and the
definition's constants. Services are classes with `Request` and `Response`.

Fixed-size numeric arrays are numpy arrays and numeric sequences `array.array`s, as in rclpy
(numpy is imported only by a type that has such an array). ROS 1 code reads a stamp as
`secs`/`nsecs` and a header's `seq`: `builtin_interfaces/Time` answers to both spellings and
`std_msgs/Header` carries a `seq` that is not sent (ROS 2 has none). rospy also takes whole
numbers for floats (`lenient()`), as ROS 1 did.

Instances are written as CDR directly (launcher's CDR writer reads fields by name); received
messages, requests and responses are built as these classes by the reader (`make`), without
the checks.
"""

from __future__ import annotations

import array
import math
import operator
from collections.abc import Callable
from typing import Any

from launcher.bus import kinds
from launcher.bus.message_class import assigner
from launcher.bus.types import normalize, registry
from launcher.bus.wire import stamp_nanoseconds, stamp_seconds

_INT_RANGES = {"byte": (0, 255), "char": (0, 255), "octet": (0, 255),
               "int8": (-2**7, 2**7 - 1), "uint8": (0, 255),
               "int16": (-2**15, 2**15 - 1), "uint16": (0, 2**16 - 1),
               "int32": (-2**31, 2**31 - 1), "uint32": (0, 2**32 - 1),
               "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1)}
_IDL_NAMES = {"float64": "double", "float32": "float", "bool": "boolean", "byte": "octet",
              "char": "uint8"}
_TYPECODES = {"float64": "d", "float32": "f", "int8": "b", "uint8": "B", "byte": "B",
              "char": "B", "int16": "h", "uint16": "H", "int32": "i", "uint32": "I",
              "int64": "q", "uint64": "Q"}
_DTYPES = {"byte": "uint8", "char": "uint8"}

_classes: dict[str, type] = {}
_services: dict[str, type] = {}
_lenient = False


def lenient() -> None:
    """Take ints for float fields from now on (rospy: ROS 1 converted them when sending)."""
    global _lenient
    _lenient = True


class Slot:
    """One of `SLOT_TYPES`: the field's type as rosidl_parser names it."""

    def __init__(self, text: str) -> None:
        self.text = text

    def __repr__(self) -> str:
        return self.text

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Slot) and other.text == self.text

    def __hash__(self) -> int:
        return hash(self.text)


class Message:
    """What every generated class shares; the class attributes are set per type."""

    __slots__ = ()
    _TYPE: str = ""
    _FIELDS: tuple[str, ...] = ()
    _DEFAULTS: tuple[Callable[[], Any], ...] = ()
    _FIELD_TYPES: dict[str, str] = {}

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        if len(args) > len(self._FIELDS):
            raise TypeError(f"{type(self).__name__}() takes at most {len(self._FIELDS)} "
                            f"positional arguments ({len(args)} given)")
        unknown = sorted(k for k in kwargs if k not in self._FIELDS)
        if unknown:
            raise AssertionError("Invalid arguments passed to constructor: "
                                 + ", ".join(unknown))
        values = dict(zip(self._FIELDS, args, strict=False))
        for name in kwargs:
            if name in values:
                raise TypeError(f"{type(self).__name__}() got multiple values for '{name}'")
        values.update(kwargs)
        for name, default in zip(self._FIELDS, self._DEFAULTS, strict=True):
            if name in values:
                setattr(self, name, values[name])
            else:
                object.__setattr__(self, "_" + name, default())

    @classmethod
    def get_fields_and_field_types(cls) -> dict[str, str]:
        return dict(cls._FIELD_TYPES)

    def __repr__(self) -> str:
        cls = type(self)
        parts = [f"{name}={_repr(getattr(self, name))}" for name in self._FIELDS]
        return f"{cls.__module__}.{cls.__qualname__}({', '.join(parts)})"

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return False
        return all(_equal(getattr(self, n), getattr(other, n)) for n in self._FIELDS)

    __hash__ = None  # type: ignore[assignment]  # mutable, as rclpy's messages are


def _repr(value: Any) -> str:
    if isinstance(value, array.array):
        return f"array('{value.typecode}', {value.tolist()!r})"
    if type(value).__name__ == "ndarray":
        return f"numpy.array({value.tolist()!r})"
    return repr(value)


def _equal(a: Any, b: Any) -> bool:
    if type(a).__name__ == "ndarray" or type(b).__name__ == "ndarray":
        return bool(len(a) == len(b) and all(x == y for x, y in zip(a, b, strict=True)))
    return bool(a == b)


# --- field kinds --------------------------------------------------------------------------
def _idl(kind: int, detail: Any) -> str:
    if kind == kinds.BASE:
        base, bound = detail
        name = _IDL_NAMES.get(base, base)
        return f"{name}<={bound}" if bound and base in ("string", "wstring") else name
    if kind == kinds.NAME:
        package, _, name = detail.split("/")
        return f"{package}/{name}"
    (inner_kind, inner_detail), count = detail
    inner = _idl(inner_kind, inner_detail)
    if kind == kinds.ARRAY:
        return f"{inner}[{count}]"
    return f"sequence<{inner}, {count}>" if count else f"sequence<{inner}>"


def _default(kind: int, detail: Any) -> Callable[[], Any]:
    if kind == kinds.BASE:
        base = detail[0]
        if base in ("string", "wstring"):
            return str
        if base == "bool":
            return bool
        if base in ("float32", "float64"):
            return float
        return int
    if kind == kinds.NAME:
        return lambda: message_class(detail)()
    (inner_kind, inner_detail), count = detail
    if inner_kind == kinds.BASE and inner_detail[0] not in ("string", "wstring", "bool"):
        code = _TYPECODES[inner_detail[0]]
        if kind == kinds.ARRAY:
            dtype = _DTYPES.get(inner_detail[0], inner_detail[0])

            def zeros() -> Any:
                import numpy

                return numpy.zeros(count, dtype=dtype)
            return zeros
        return lambda: array.array(code)
    if kind == kinds.ARRAY:
        item = _default(inner_kind, inner_detail)
        return lambda: [item() for _ in range(count)]
    return list


def _written_default(field: str, kind: int, detail: Any, value: Any) -> Callable[[], Any]:
    """A field's default value from its definition, stored as a value set would be."""
    check = _checker(field, kind, detail)
    return lambda: check(list(value) if isinstance(value, list) else value)


def _checker(field: str, kind: int, detail: Any) -> Callable[[Any], Any]:
    """A function that checks a value for the field and returns what is stored."""
    if kind == kinds.BASE:
        return _base_checker(field, detail[0], detail[1])
    if kind == kinds.NAME:
        short = detail.rsplit("/", 1)[-1]

        def nested(value: Any) -> Any:
            if not (isinstance(value, Message) and detail == value._TYPE):
                raise AssertionError(f"The '{field}' field must be a sub message of type "
                                     f"'{short}'")
            return value
        return nested
    (inner_kind, inner_detail), count = detail
    fixed = kind == kinds.ARRAY
    if inner_kind == kinds.BASE and inner_detail[0] not in ("string", "wstring", "bool"):
        base = inner_detail[0]
        python = "float" if base in ("float32", "float64") else "int"
        each = f"each value of type '{python}'"
        item = _base_checker(field, base, 0)

        def numbers(value: Any) -> Any:
            if isinstance(value, bytes | bytearray) and base in ("uint8", "byte", "char"):
                value = list(value)
            try:
                items = list(value)
                for x in items:
                    item(x)
            except (TypeError, AssertionError):
                raise AssertionError(f"The '{field}' field must be a set or sequence and "
                                     f"{each}") from None
            if fixed:
                if len(items) != count:
                    raise AssertionError(f"The '{field}' field must be a set or sequence "
                                         f"with length {count} and {each}")
                import numpy

                return numpy.array(items, dtype=_DTYPES.get(base, base))
            if count and len(items) > count:
                raise AssertionError(f"The '{field}' field must be a set or sequence with "
                                     f"length <= {count} and {each}")
            return array.array(_TYPECODES[base], items)
        return numbers
    item_check = _checker(field, inner_kind, inner_detail)
    label = (inner_detail.rsplit("/", 1)[-1] if inner_kind == kinds.NAME else
             {"string": "str", "wstring": "str", "bool": "bool"}.get(inner_detail[0], "?"))

    def items(value: Any) -> Any:
        if isinstance(value, str) or not hasattr(value, "__iter__"):
            raise AssertionError(f"The '{field}' field must be a set or sequence and each "
                                 f"value of type '{label}'")
        result = list(value)
        try:
            for x in result:
                item_check(x)
        except AssertionError:
            raise AssertionError(f"The '{field}' field must be a set or sequence and each "
                                 f"value of type '{label}'") from None
        if fixed and len(result) != count:
            raise AssertionError(f"The '{field}' field must be a set or sequence with length "
                                 f"{count} and each value of type '{label}'")
        if not fixed and count and len(result) > count:
            raise AssertionError(f"The '{field}' field must be a set or sequence with length "
                                 f"<= {count} and each value of type '{label}'")
        return result
    return items


def _base_checker(field: str, base: str, bound: int) -> Callable[[Any], Any]:
    if base in ("string", "wstring"):
        def text(value: Any) -> Any:
            if not isinstance(value, str):
                raise AssertionError(f"The '{field}' field must be of type 'str'")
            if bound and len(value) > bound:
                raise AssertionError(f"The '{field}' field must be string value not longer "
                                     f"than {bound}")
            return value
        return text
    if base == "bool":
        def boolean(value: Any) -> Any:
            if not isinstance(value, bool):
                raise AssertionError(f"The '{field}' field must be of type 'bool'")
            return value
        return boolean
    if base in ("float32", "float64"):
        limit = 3.402823466e+38 if base == "float32" else 1.7976931348623157e+308
        idl = _IDL_NAMES[base]

        def number(value: Any) -> Any:
            if not isinstance(value, float):
                if _lenient and isinstance(value, int) and not isinstance(value, bool):
                    return float(value)
                raise AssertionError(f"The '{field}' field must be of type 'float'")
            if not -limit <= value <= limit and not math.isinf(value) and not math.isnan(value):
                raise AssertionError(f"The '{field}' field must be a {idl} in "
                                     f"[{-limit}, {limit}]")
            return value
        return number
    low, high = _INT_RANGES[base]

    def whole(value: Any) -> Any:
        if isinstance(value, bytes) and len(value) == 1 and base in ("byte", "char"):
            value = value[0]
        if not isinstance(value, int):
            raise AssertionError(f"The '{field}' field must be of type 'int'")
        if not low <= value <= high:
            raise AssertionError(f"The '{field}' field must be an integer in "
                                 f"[{low}, {high}]")
        return value
    return whole


def _property(field: str, check: Callable[[Any], Any]) -> property:
    slot = "_" + field

    def put(self: Any, value: Any) -> None:
        object.__setattr__(self, slot, check(value))
    # (a getter in C: reading fields is what serialising a message does most)
    return property(operator.attrgetter(slot), put, doc=f"Message field '{field}'.")


# --- the classes ----------------------------------------------------------------------------
def message_class(type_name: str, module: str = "", qualname: str = "") -> type:
    """The class of `pkg/msg/Name` (made once per process)."""
    name = normalize(type_name)
    found = _classes.get(name)
    if found is not None:
        return found
    types = registry()
    fields = types.fields(name)  # registers it (and what it names) for CDR
    constants = types.fielddefs[name][0]
    defaults = types.defaults(name)
    package, kind, short = name.split("/")
    namespace: dict[str, Any] = {
        "__slots__": tuple("_" + f for f, _ in fields) + (("_seq",) if _ros1_header(name)
                                                          else ()),
        "__module__": module or f"{package}.{kind}",
        "__qualname__": qualname or short,
        "_TYPE": name,
        "_FIELDS": tuple(f for f, _ in fields),
        "_SLOTS": tuple("_" + f for f, _ in fields),
        "_DEFAULTS": tuple(_written_default(f, k, d, defaults[f]) if f in defaults
                           else _default(k, d) for f, (k, d) in fields),
        "_FIELD_TYPES": {f: _idl(k, d) for f, (k, d) in fields},
        "SLOT_TYPES": tuple(Slot(_idl(k, d)) for _, (k, d) in fields),
    }
    for field, (k, d) in fields:
        namespace[field] = _property(field, _checker(field, k, d))
    for constant, _kind, value in constants:
        namespace[constant] = value
    if name == "builtin_interfaces/msg/Time":
        namespace.update(_ROS1_TIME)
    if _ros1_header(name):
        namespace["seq"] = property(lambda self: getattr(self, "_seq", 0),
                                    lambda self, v: object.__setattr__(self, "_seq", int(v)))
    cls = type(qualname or short, (Message,), namespace)
    _classes[name] = cls
    return cls


def _ros1_header(name: str) -> bool:
    return name == "std_msgs/msg/Header"


def _secs(self: Any) -> int:
    return self.sec


def _set_secs(self: Any, value: int) -> None:
    self.sec = value


def _nsecs(self: Any) -> int:
    return self.nanosec


def _set_nsecs(self: Any, value: int) -> None:
    self.nanosec = value


_ROS1_TIME = {
    "secs": property(_secs, _set_secs), "nsecs": property(_nsecs, _set_nsecs),
    "to_sec": stamp_seconds,
    "to_nsec": stamp_nanoseconds,
}


def service_class(type_name: str) -> type:
    """The class of `pkg/srv/Name`, with `Request` and `Response`."""
    name = normalize(type_name)
    found = _services.get(name)
    if found is not None:
        return found
    request, response = registry().service(name)
    package, kind, short = name.split("/")
    module = f"{package}.{kind}"
    cls = type(short, (), {
        "__module__": module, "_TYPE": name,
        "Request": message_class(request, module, f"{short}_Request"),
        "Response": message_class(response, module, f"{short}_Response"),
    })
    _services[name] = cls
    return cls


_actions: dict[str, type] = {}


def action_class(type_name: str) -> type:
    """The class of `pkg/action/Name`, as rosidl generates it: `Goal`, `Result`, `Feedback`,
    and `Impl` with the services and messages rclpy.action speaks (`SendGoalService`,
    `GetResultService`, `CancelGoalService`, `FeedbackMessage`, `GoalStatusMessage`)."""
    name = normalize(type_name)
    found = _actions.get(name)
    if found is not None:
        return found
    registry().action(name)
    package, kind, short = name.split("/")
    module = f"{package}.{kind}"
    impl = type("Impl", (), {
        "__module__": module, "__qualname__": f"{short}.Impl",
        "SendGoalService": service_class(f"{name}_SendGoal"),
        "GetResultService": service_class(f"{name}_GetResult"),
        "CancelGoalService": service_class("action_msgs/srv/CancelGoal"),
        "FeedbackMessage": message_class(f"{name}_FeedbackMessage", module,
                                         f"{short}_FeedbackMessage"),
        "GoalStatusMessage": message_class("action_msgs/msg/GoalStatusArray"),
    })
    cls = type(short, (), {
        "__module__": module, "_TYPE": name,
        "Goal": message_class(f"{name}_Goal", module, f"{short}_Goal"),
        "Result": message_class(f"{name}_Result", module, f"{short}_Result"),
        "Feedback": message_class(f"{name}_Feedback", module, f"{short}_Feedback"),
        "Impl": impl,
    })
    _actions[name] = cls
    return cls


def type_name_of(value: Any) -> str:
    """`pkg/msg/Name` (or `pkg/srv/Name`) of a class from here, or a type name given as text."""
    if isinstance(value, str):
        return normalize(value)
    name = getattr(value, "_TYPE", None)
    if not isinstance(name, str) or "/" not in name:
        raise TypeError(f"expected a message or service class, got {value!r}")
    return name


# --- from received payloads ------------------------------------------------------------
def make(type_name: str, values: list[Any]) -> Any:
    """A message from its field values as the CDR reader gives them (registry().deserialize's
    `make`): numeric sequences stay array.arrays, fixed numeric arrays become numpy arrays."""
    fill = _fillers.get(type_name)
    if fill is None:
        cls = _classes.get(type_name) or message_class(type_name)
        fill = _fillers[type_name] = (cls, assigner(cls._SLOTS, f"{cls.__qualname__}.fill"),
                                      _fixed_arrays(cls))
    cls, assign, fixed = fill
    if fixed:
        import numpy

        for index, dtype in fixed.items():
            values[index] = numpy.array(values[index], dtype=dtype)
    message = _new(cls)
    assign(message, *values)  # every slot, by code as fast as written out
    return message


_fillers: dict[str, tuple[type, Callable[..., None], dict[int, str]]] = {}
_new = object.__new__


def _fixed_arrays(cls: Any) -> dict[int, str]:
    """{field index: numpy dtype} of the type's fixed numeric arrays (kept in `_fillers`)."""
    found = {}
    for index, (_, (kind, detail)) in enumerate(registry().fields(cls._TYPE)):
        if kind == kinds.ARRAY and detail[0][0] == kinds.BASE and detail[0][1][0] in _TYPECODES:
            found[index] = _DTYPES.get(detail[0][1][0], detail[0][1][0])
    return found
