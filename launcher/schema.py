"""Declared fields: a record (an action, a bridge entry, a node's options or parameters, a
sim plugin's parameters) states its fields once, as data, and one builder turns what a user
wrote into it, with the same checks and messages everywhere.

`attr(...)` goes into a dataclass field's metadata; `build(cls, values, where)` makes a record
from values already read (YAML, a command line, XML children, ROS parameters): unknown keys
are refused (or warned about) with "did you mean", required ones must be there, and each value
is coerced to its kind, leniently about spelling and strictly about meaning. `problem` is the
one check of a value against what a declaration says of it (required, choices, bounds), in the
one wording: these fields' and a node's declared parameters' (bus/declarations.py). This
module imports only `errors` and `records`: every layer may declare with it.
"""

from __future__ import annotations

import enum
import math
import re
from collections.abc import Callable, Mapping
from typing import Any, NamedTuple, Protocol, TypeVar

from launcher import records
from launcher.errors import Location, ParseError, did_you_mean


class Kind(enum.Enum):
    TEXT = "text"  # substitution text (in launch files), text elsewhere
    NAME = "name"  # plain text, taken as written (names that must be known before running)
    BOOL = "bool"  # true/false, possibly from a substitution
    FLOAT = "float"  # a number, possibly from a substitution
    INT = "int"
    COMMAND = "command"  # a command line: split like a shell, substitutions not split
    ENTRIES = "entries"  # a list of nested records (env, arg, keep, choice, …)
    ACTIONS = "actions"  # a list of actions given under this attribute (on_exit, on_start)
    CHILDREN = "children"  # the tag's children
    NAMES = "names"  # a list of texts (a repeatable element, as a plugin's <left_joint>)
    VALUE = "value"  # a ROS parameter value: text or a list, typed when it is used


class Attr(NamedTuple):
    kind: Kind
    name: str | None = None  # the spelling users write when it differs from the field name
    aliases: tuple[str, ...] = ()
    required: bool = False
    doc: str = ""
    entry: type | None = None  # the record type of ENTRIES
    minimum: float | None = None  # for numbers: the smallest valid value
    choices: tuple[str, ...] = ()  # for TEXT and NAMES (each name): the valid literal values
    maximum: float | None = None  # for numbers: the largest valid value
    above: float | None = None  # for numbers: what a valid value must exceed (> 0, not ≥ 0)
    below: float | None = None  # for numbers: what a valid value must stay under


LISTS = (Kind.ENTRIES, Kind.ACTIONS, Kind.CHILDREN, Kind.NAMES)
R = TypeVar("R")


def attr(kind: Kind, default: Any = None, **spec: Any) -> Any:
    """A dataclass field carrying its declaration."""
    meta = {"launch": Attr(kind, **spec)}
    if kind in LISTS and default is None:
        return records.field(default_factory=list, metadata=meta)
    return records.field(default=default, metadata=meta)


def declared_fields(cls: type) -> list[tuple[records.Field, Attr]]:
    return [(f, f.metadata["launch"]) for f in records.fields(cls) if "launch" in f.metadata]


def frontend_name(f: records.Field, spec: Attr) -> str:
    return spec.name or f.name


# --- the one check of a value against its declaration ---------------------------------------
class Declared(Protocol):
    """What a declaration says of its values: an Attr, or a node's declared parameter."""

    @property
    def required(self) -> bool: ...
    @property
    def choices(self) -> tuple[str, ...]: ...
    @property
    def minimum(self) -> float | None: ...
    @property
    def maximum(self) -> float | None: ...
    @property
    def above(self) -> float | None: ...
    @property
    def below(self) -> float | None: ...


# each bound: its declaration's field, its sign, and when a value falls outside it
_BOUNDS: tuple[tuple[str, str, Callable[[float, float], bool]], ...] = (
    ("minimum", "≥", lambda value, bound: value < bound),
    ("above", ">", lambda value, bound: value <= bound),
    ("maximum", "≤", lambda value, bound: value > bound),
    ("below", "<", lambda value, bound: value >= bound),
)


def problem(value: Any, spec: Declared, what: str, shown: str = "") -> str | None:
    """What is wrong with `value` (None: not given) by its declaration, as `what: expected
    …, got …`; None when nothing is. A list's items are checked one by one (each must be one
    of the choices). `shown`: the value as the user wrote it, when that differs."""
    if value is None:
        return f"{what} is required" if spec.required else None
    for item in value if isinstance(value, list | tuple) else (value,):
        found = _outside_choices(item, spec, what) or \
            _outside_bounds(item, spec, what, shown or str(item))
        if found:
            return found
    return None


def _outside_choices(item: Any, spec: Declared, what: str) -> str | None:
    if not spec.choices or item in spec.choices:
        return None
    return (f"{what}: expected one of {', '.join(spec.choices)}, got '{item}'"
            f"{did_you_mean(str(item), spec.choices)}")


def _outside_bounds(item: Any, spec: Declared, what: str, shown: str) -> str | None:
    """Out of a bound: a finite number only (an infinity or NaN says "no limit", as a speed
    limit of .inf does)."""
    if not isinstance(item, int | float) or isinstance(item, bool) or not math.isfinite(item):
        return None
    for key, sign, outside in _BOUNDS:
        bound = getattr(spec, key)
        if bound is not None and outside(item, bound):
            return f"{what}: expected a number {sign} {_plain(bound)}, got {shown}"
    return None


def _plain(number: float) -> str:
    """A bound as users write it: 1 for 1.0, 0.001 as it is."""
    return str(int(number) if float(number).is_integer() else number)


# --- coercion: lenient about spelling, strict about meaning --------------------------------
_TRUE = {"true", "1", "yes", "on"}
_FALSE = {"false", "0", "no", "off"}


def coerce(kind: Kind, text: str, what: str, spec: Attr | None = None) -> Any:
    """Turn `text` into the value of `kind`, or raise ParseError saying what was expected."""
    value: Any
    if kind is Kind.BOOL:
        low = text.strip().lower()
        if low in _TRUE:
            return True
        if low in _FALSE:
            return False
        raise ParseError(f"{what}: expected true or false, got '{text}'")
    if kind in (Kind.FLOAT, Kind.INT):
        try:
            value = float(text) if kind is Kind.FLOAT else int(text.strip())
        except ValueError:
            expected = "a number" if kind is Kind.FLOAT else "a whole number"
            raise ParseError(f"{what}: expected {expected}, got '{text}'") from None
        if isinstance(value, float) and not math.isfinite(value):
            raise ParseError(f"{what}: expected a finite number, got '{text}'")
        return _checked(value, what, spec, text.strip())
    return _checked(text, what, spec)


def _checked(value: Any, what: str, spec: Attr | None, shown: str = "") -> Any:
    found = problem(value, spec, what, shown) if spec is not None else None
    if found:
        raise ParseError(found)
    return value


def value_of(kind: Kind, value: Any, what: str, spec: Attr | None = None) -> Any:
    """A value read from YAML, a command line or a parameter, as `kind`: text is coerced,
    typed values are checked (a YAML `true` is no number; 3 is a fine float)."""
    if kind is Kind.NAMES and isinstance(value, str):
        return _checked([value], what, spec)  # a repeatable element given once
    if isinstance(value, str):
        return coerce(kind, value, what, spec)
    if kind is Kind.BOOL and isinstance(value, bool):
        return value
    if kind in (Kind.FLOAT, Kind.INT) and isinstance(value, int | float) and \
            not isinstance(value, bool):
        if kind is Kind.INT and not float(value).is_integer():
            raise ParseError(f"{what}: expected a whole number, got {value!r}")
        return coerce(kind, str(int(value) if kind is Kind.INT else value), what, spec)
    if kind is Kind.NAMES and isinstance(value, list | tuple):
        return _checked([str(item) for item in value], what, spec)
    if kind in (Kind.TEXT, Kind.NAME) and isinstance(value, int | float | bool):
        return coerce(kind, str(value).lower() if isinstance(value, bool) else str(value),
                      what, spec)
    expected = {Kind.BOOL: "true or false", Kind.FLOAT: "a number", Kind.INT: "a whole number",
                Kind.NAMES: "a list"}.get(kind, "text")
    raise ParseError(f"{what}: expected {expected}, got {value!r}")


def build(cls: type[R], values: Mapping[str, Any], where: str = "", *,
          unknown: str = "error", warn: Callable[[str], None] | None = None,
          places: Mapping[str, tuple[Location, Location]] | None = None,
          at: Location | None = None) -> R:
    """A `cls` record from `values` keyed by the spellings users write. `unknown`: "error"
    refuses a key that is not declared, "warn" tells `warn` and goes on, "ignore" skips it.
    `places` (key → where the key is, where its value is) puts an error at its place: an
    unknown key at the key, a bad value at the value; a missing key at `at`."""
    try:
        return _build(cls, values, where, unknown, warn, places or {})
    except ParseError as exc:
        raise exc.at(at) from None


def _build(cls: type[R], values: Mapping[str, Any], where: str, unknown: str,
           warn: Callable[[str], None] | None,
           places: Mapping[str, tuple[Location, Location]]) -> R:
    prefix = f"{where}: " if where else ""
    fields = declared_fields(cls)
    spellings = {}
    for f, spec in fields:
        for spelling in (frontend_name(f, spec), *spec.aliases):
            spellings[spelling] = (f, spec)
    valid = [frontend_name(f, spec) for f, spec in fields]
    kwargs: dict[str, Any] = {}
    for key, value in values.items():
        if key not in spellings:
            if unknown == "ignore":
                continue
            message = (f"{prefix}unknown key '{key}'{did_you_mean(str(key), valid)}; "
                       f"expected {', '.join(valid)}")
            if unknown == "warn" and warn is not None:
                warn(f"{message}; it is ignored")
                continue
            raise ParseError(message, places[key][0] if key in places else None)
        f, spec = spellings[key]
        try:
            kwargs[f.name] = value_of(spec.kind, value, f"{prefix}{key}", spec)
        except ParseError as exc:
            raise exc.at(places[key][1] if key in places else None) from None
    for f, spec in fields:
        if f.name not in kwargs:
            _checked(None, f"{prefix}{frontend_name(f, spec)}", spec)
    return cls(**kwargs)


_UNITS = {"": 1, "b": 1, "k": 10**3, "kb": 10**3, "m": 10**6, "mb": 10**6, "g": 10**9,
          "gb": 10**9, "t": 10**12, "tb": 10**12, "kib": 2**10, "mib": 2**20, "gib": 2**30,
          "tib": 2**40}
_SIZE = re.compile(r"^\s*(\d+(?:\.\d+)?)\s*([a-zA-Z]*)\s*$")


def parse_bytes(text: str, what: str) -> int:
    """A size in bytes from words like `2GiB`, `100MB`, `512k` or `4096` (> 0)."""
    found = _SIZE.match(str(text))
    unit = found.group(2).lower() if found else ""
    if not found or unit not in _UNITS or float(found.group(1)) * _UNITS[unit] < 1:
        raise ParseError(f"{what}: expected bytes or a size like 2GiB, got '{text}'")
    return int(float(found.group(1)) * _UNITS[unit])
