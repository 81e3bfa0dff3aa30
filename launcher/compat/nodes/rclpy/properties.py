"""The properties rclpy's classes have in runs, one line each: `readonly` reads an attribute
(`topic_name` is `self._bus.topic`), `stored` keeps a settable value in a private one, through a
conversion that may refuse it. docs/_gen/reference_python.py documents them from their `doc`."""

from __future__ import annotations

from collections.abc import Callable
from operator import attrgetter
from typing import Any


def readonly(path: str, doc: str) -> Any:
    """A read-only property whose value is `self.<path>` (dotted: `_goal.state`)."""
    return property(attrgetter(path), doc=doc)


def stored(attr: str, doc: str, convert: Callable[[Any], Any] | None = None) -> Any:
    """A property kept in `self.<attr>`; a value set is kept as `convert(value)` (which raises
    for one it refuses)."""
    def setter(self: Any, value: Any) -> None:
        setattr(self, attr, value if convert is None else convert(value))
    return property(attrgetter(attr), setter, doc=doc)
