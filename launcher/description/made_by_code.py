"""Where code of the user's made an action or substitution (its file and line), so that a
failure of one made by a Python launch file or an OpaqueFunction is said there, as a YAML or
XML one is said at its tag.

Only while the user's code runs (`writing()`), as the Python loader and OpaqueFunction call
it: then each entity made notes the nearest frame outside launcher. Launch files in YAML and
XML pay nothing.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, TypeVar

from launcher.errors import Location

OURS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the launcher package
_depth = 0
T = TypeVar("T")


@contextmanager
def writing() -> Iterator[None]:
    """While the user's code runs: entities made note where."""
    global _depth
    _depth += 1
    try:
        yield
    finally:
        _depth -= 1


def note(entity: object) -> None:
    """Give `entity` the place in the user's code that made it (when code is being run)."""
    if _depth:
        place = caller()
        if place is not None:
            object.__setattr__(entity, "made_at", place)


_installed: tuple[str, ...] | None = None


def users(filename: str) -> bool:
    """Whether a frame's file is the user's: not launcher's, Python's or an installed
    library's (so that a failure inside the standard library is not said as theirs)."""
    global _installed
    if _installed is None:
        import sysconfig

        paths = sysconfig.get_paths()
        _installed = tuple({paths[k] for k in ("stdlib", "platstdlib", "purelib", "platlib")})
    return not filename.startswith((OURS, "<", *_installed))


def caller() -> Location | None:
    frame = sys._getframe(2)
    while frame is not None:
        if users(frame.f_code.co_filename):
            return Location(frame.f_code.co_filename, frame.f_lineno)
        frame = frame.f_back  # type: ignore[assignment]
    return None


def place_of(exc: BaseException) -> Location | None:
    """The innermost frame of the user's code in `exc`'s traceback."""
    import traceback  # only for an error: start-up time

    for summary in reversed(traceback.extract_tb(exc.__traceback__)):
        if users(summary.filename):
            return Location(summary.filename, summary.lineno or 0)
    return None


def defined_at(function: Callable[..., Any]) -> Location | None:
    """Where a function (or a method) of the user's is defined."""
    code = getattr(getattr(function, "__func__", function), "__code__", None)
    return None if code is None else Location(code.co_filename, code.co_firstlineno)
