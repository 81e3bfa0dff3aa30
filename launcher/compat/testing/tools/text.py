"""launch_testing.tools.text: matchers of expected output. A matcher is called with the actual
text (or lines) and where to start, and gives (start, end) of what it found, or None.

An expectation is a text (found in it), a compiled regular expression (searched; matched
line by line for lines), or a list of them found one after the other. `strict`: the text
(every line) must be the expectation itself, nothing before or after it."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from typing import Any

Match = Callable[..., "tuple[int, int] | None"]


def normalize_lineseps(lines: str) -> str:
    r"""`lines` (a text) with every line ending a '\n' (a pseudo-terminal's '\r\n' included)."""
    return lines.replace(os.linesep, "\n").replace("\r\n", "\n")


def build_line_match(expected_lines: Any, *, strict: bool = False) -> Match:
    """A matcher of a list of lines against `expected_lines`."""
    if isinstance(expected_lines, str) or hasattr(expected_lines, "match"):
        if isinstance(expected_lines, str):
            def one(line: str) -> bool:
                return (expected_lines == line) if strict else (expected_lines in line)
        else:
            def one(line: str) -> bool:
                return bool(expected_lines.match(line))

        def match_line(lines: list[str], start: int = 0) -> tuple[int, int] | None:
            if strict:
                return (start, len(lines)) if all(one(line) for line in lines[start:]) \
                    else None
            return next(((i, i + 1) for i in range(start, len(lines)) if one(lines[i])), None)
        return match_line
    if isinstance(expected_lines, Iterable):
        return _in_order([build_line_match(part) for part in expected_lines], strict)
    raise ValueError("Unknown format for expected lines")


def build_text_match(expected_text: Any, *, strict: bool = False) -> Match:
    """A matcher of a text against `expected_text`."""
    if isinstance(expected_text, str):
        def match_text(text: str, start: int = 0) -> tuple[int, int] | None:
            text = normalize_lineseps(text)
            if strict:
                return (start, start + len(expected_text)) \
                    if text[start:] == expected_text else None
            found = text.find(expected_text, start)
            return None if found < 0 else (found, found + len(expected_text))
        return match_text
    if hasattr(expected_text, "search") and hasattr(expected_text, "match"):
        def match_pattern(text: str, start: int = 0) -> tuple[int, int] | None:
            text = normalize_lineseps(text)
            found = (expected_text.match if strict else expected_text.search)(text, start)
            return None if found is None else (found.start(), found.end())
        return match_pattern
    if isinstance(expected_text, Iterable):
        parts = [build_text_match(part) for part in expected_text]

        def match_parts(text: str, start: int = 0) -> tuple[int, int] | None:
            return _in_order(parts, strict)(normalize_lineseps(text), start)
        return match_parts
    raise ValueError("Unknown format for expected text")


def _in_order(parts: list[Match], strict: bool) -> Match:
    """Each of `parts` found after the one before (strict: right after, from the start)."""
    def match(actual: Any, start: int = 0) -> tuple[int, int] | None:
        if not parts:
            return start, start
        first = parts[0](actual, start)
        if first is None or strict and first[0] != start:
            return None
        begin, end = first
        for part in parts[1:]:
            found = part(actual, end)
            if found is None or strict and found[0] != end:
                return None
            end = found[1]
        return begin, end
    return match
