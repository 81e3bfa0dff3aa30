"""Field declarations for actions: each action states its fields once, as data (with
launcher/schema.py, which every config of launcher declares with).

The frontend builder reads them to map a YAML map or XML element onto the action, coerce values
and reject leftovers; `--print` and the docs read the same declarations. What is particular to
launch files lives here: values that are substitutions, resolved and coerced at run time.
"""

from __future__ import annotations

from typing import Any

from launcher.description.substitution import perform_text, to_text
from launcher.errors import ParseError, SubstitutionError
from launcher.runtime.context import LaunchContext
from launcher.schema import Attr, Kind, attr, coerce, declared_fields, frontend_name

__all__ = ["Attr", "Kind", "attr", "coerce", "declared_fields", "frontend_name", "normalize",
           "resolve"]


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
        if value is None or spec.kind in (Kind.NAME, Kind.ENTRIES, Kind.ACTIONS, Kind.CHILDREN,
                                             Kind.VALUE):
            continue
        if spec.kind is Kind.COMMAND and isinstance(value, list):
            setattr(obj, field.name, [to_text(item) for item in value])
        elif spec.kind in (Kind.TEXT, Kind.COMMAND) or not isinstance(value, bool | int | float):
            setattr(obj, field.name, to_text(value))
