"""Field declarations for actions: each action states its fields once, as data.

`attr(...)` goes into a dataclass field's metadata. The frontend builder reads it to map a YAML
map or XML element onto the action, coerce values and reject leftovers; `--print` and the docs
read the same declarations.
"""

from __future__ import annotations

import dataclasses
import enum
import math
from typing import Any, NamedTuple

from launcher.description.substitution import perform_text, to_text
from launcher.errors import ParseError, SubstitutionError
from launcher.runtime.context import LaunchContext


class Kind(enum.Enum):
    TEXT = "text"  # substitution text
    NAME = "name"  # plain text, taken as written (names that must be known before running)
    BOOL = "bool"  # true/false, possibly from a substitution
    FLOAT = "float"  # a number, possibly from a substitution
    INT = "int"
    COMMAND = "command"  # a command line: split like a shell, substitutions not split
    ENTRIES = "entries"  # a list of nested records (env, arg, keep, choice, …)
    ACTIONS = "actions"  # a list of actions given under this attribute (on_exit, on_start)
    CHILDREN = "children"  # the tag's children


class Attr(NamedTuple):
    kind: Kind
    name: str | None = None  # the frontend spelling when it differs from the field name
    aliases: tuple[str, ...] = ()
    required: bool = False
    doc: str = ""
    entry: type | None = None  # the record type of ENTRIES
    minimum: float | None = None  # for numbers: the smallest valid value
    choices: tuple[str, ...] = ()  # for TEXT: the valid literal values


def attr(kind: Kind, default: Any = None, **spec: Any) -> Any:
    """A dataclass field carrying its frontend declaration."""
    factory = list if kind in (Kind.ENTRIES, Kind.ACTIONS, Kind.CHILDREN) else None
    meta = {"launch": Attr(kind, **spec)}
    if factory is not None and default is None:
        return dataclasses.field(default_factory=factory, metadata=meta)
    return dataclasses.field(default=default, metadata=meta)


def declared_fields(cls: type) -> list[tuple[dataclasses.Field, Attr]]:
    return [(f, f.metadata["launch"]) for f in dataclasses.fields(cls) if "launch" in f.metadata]


def frontend_name(f: dataclasses.Field, spec: Attr) -> str:
    return spec.name or f.name


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
        if spec is not None and spec.minimum is not None and value < spec.minimum:
            bound = int(spec.minimum) if float(spec.minimum).is_integer() else spec.minimum
            raise ParseError(f"{what}: expected a number ≥ {bound}, got {text.strip()}")
        return value
    if spec is not None and spec.choices and text not in spec.choices:
        raise ParseError(
            f"{what}: expected one of {', '.join(spec.choices)}, got '{text}'"
        )
    return text


def resolve(context: LaunchContext, value: Any, kind: Kind, what: str,
            spec: Attr | None = None) -> Any:
    """The value of a typed field at run time: literals pass, substitution text is coerced."""
    if value is None or isinstance(value, bool | int | float) and kind is not Kind.TEXT:
        if spec is not None and isinstance(value, int | float) and not isinstance(value, bool):
            coerce(kind, str(value), what, spec)
        return value
    text = perform_text(context, to_text(value))
    try:
        return coerce(kind, text, what, spec)
    except ParseError as exc:
        raise SubstitutionError(exc.message) from None


def normalize(obj: Any) -> None:
    """Python API values (str, numbers, substitutions, lists) → the forms the builder makes."""
    for field, spec in declared_fields(type(obj)):
        value = getattr(obj, field.name)
        if value is None or spec.kind in (Kind.NAME, Kind.ENTRIES, Kind.ACTIONS, Kind.CHILDREN):
            continue
        if spec.kind is Kind.COMMAND and isinstance(value, list):
            setattr(obj, field.name, [to_text(item) for item in value])
        elif spec.kind in (Kind.TEXT, Kind.COMMAND) or not isinstance(value, bool | int | float):
            setattr(obj, field.name, to_text(value))
