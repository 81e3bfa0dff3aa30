"""launch.frontend.parse_substitution: `$(name arg …)` in a launch file's text, read by
launcher's substitution parser (launcher.frontend.substitution_parser) and made into the
substitutions launcher's registry holds, built-in and exposed (launch.frontend.expose) alike."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from typing import Any

from launch.substitutions import TextSubstitution
from launcher.description.registry import Registry, default_registry
from launcher.description.substitution import Substitution, Text, to_text
from launcher.errors import Location
from launcher.frontend.builder import parse_substitutions
from launcher.frontend.entity import Attribute

__all__ = ["TextSubstitution", "instantiate_substitution", "parse_if_substitutions",
           "parse_substitution", "replace_escaped_characters"]

_ESCAPED = re.compile(r"\\(.)")
_TEXT = Location("<text>")


def replace_escaped_characters(data: str) -> str:
    """`\\x` → `x`, for every character x."""
    return _ESCAPED.sub(r"\1", data)


def as_launch_text(parts: Iterable[Substitution]) -> list[Substitution]:
    """Substitutions as launch gives them: literal text as launch's TextSubstitution."""
    return [TextSubstitution(text=p.text) if type(p) is Text else p for p in parts]


def substitutions_in(text: str, registry: Registry, where: Location | None) -> list[Any]:
    """The substitutions written in `text`; a syntax error or an unknown name is a
    ParseError (at `where`, the place of the entity the text belongs to)."""
    parts = as_launch_text(parse_substitutions(Attribute(text, where or _TEXT), registry))
    return parts or [TextSubstitution(text=text)]


def parse_substitution(string_value: str) -> list[Any]:
    return substitutions_in(string_value, default_registry(), None)


def instantiate_substitution(type_name: str, args: Iterable[Any] | None = None) -> Any:
    """The substitution `$(type_name args…)`, each argument text or substitutions."""
    found = default_registry().find_substitution(type_name)
    if found is None:
        raise RuntimeError(f"Unknown substitution: {type_name}")
    return found.from_args([to_text(arg) for arg in args or ()], None)


def parse_if_substitutions(value: Any) -> Any:
    """Texts with substitutions made into lists of substitutions (plain text left as str),
    other scalars as they are, item by item in a list, which must stay uniform.

    Raises ValueError for a list that is not."""
    return parse_if_with(value, parse_substitution)


def parse_if_with(value: Any, parse: Callable[[str], list[Any]]) -> Any:
    kinds: set[type] = set()

    def one(item: Any) -> Any:
        if not isinstance(item, str):
            kinds.add(type(item))
            return item
        parts = parse(item)
        if len(parts) == 1 and isinstance(parts[0], Text):
            kinds.add(str)
            return parts[0].text
        return parts

    out = [one(x) for x in value] if isinstance(value, list) else one(value)
    if len(kinds) > 1:
        raise ValueError("The result is a non-uniform list")
    return out
