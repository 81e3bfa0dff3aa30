"""launch_testing.tools.output: filters of a process's output, expected output from a file,
and expect_output (does the output match an expectation)."""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from typing import Any

from launcher.compat.testing.tools.text import build_line_match, build_text_match

ANSI = re.compile(r"\x1b\[[0-?]*[ -/]*[@-~]")  # an ANSI escape sequence (colours, cursor)


def remove_ansi_escape_sequences(text: str) -> str:
    return ANSI.sub("", text)


def get_default_filtered_prefixes() -> list[str]:
    return ["pid", "rc"]


def get_default_filtered_patterns() -> list[str]:
    return []


def rmw_output_filter(rmw_implementation: str, filter_type: str) -> list[str]:
    """The `filter_type` ('prefixes' or 'patterns') lines `rmw_implementation` prints that
    tests ignore: its `rmw_output_prefixes` or `rmw_output_patterns` resource in the package
    index, as ROS 2 keeps them (launch_testing_ros's get_rmw_output_filter)."""
    if filter_type not in ("prefixes", "patterns"):
        raise TypeError(f'Unsupported filter_type "{filter_type}". Supported types: '
                        "['prefixes', 'patterns']")
    import ament_index_python

    resource = f"rmw_output_{filter_type}"
    if not ament_index_python.has_resource(resource, rmw_implementation):
        return []
    content, _ = ament_index_python.get_resource(resource, rmw_implementation)
    return content.splitlines()


def basic_output_filter(filtered_prefixes: list[str] | None = None,
                        filtered_patterns: list[str] | None = None) -> Callable[[str], str]:
    """A filter of output text that drops the lines starting with one of `filtered_prefixes`
    (default: 'pid' and 'rc') or matching one of `filtered_patterns` (regular expressions)."""
    prefixes = tuple(get_default_filtered_prefixes() if filtered_prefixes is None
                     else filtered_prefixes)
    patterns = [re.compile(p) for p in (get_default_filtered_patterns()
                                        if filtered_patterns is None else filtered_patterns)]

    def keep(line: str) -> bool:
        return not line.startswith(prefixes) and not any(p.match(line) for p in patterns)

    def output_filter(output: str) -> str:
        return "".join(line for line in output.splitlines(keepends=True) if keep(line))
    return output_filter


def expected_output_from_file(path: str, encoding: str | None = None) -> list[Any]:
    """The expected lines in `path`.txt (texts), or else in `path`.regex (patterns)."""
    if os.path.isfile(path + ".txt"):
        with open(path + ".txt", encoding=encoding) as f:
            return f.read().splitlines()
    if os.path.isfile(path + ".regex"):
        with open(path + ".regex", encoding=encoding) as f:
            return [re.compile(line) for line in f.read().splitlines()]
    raise RuntimeError(f"could not find output check file: {path}")


def expect_output(text: str | None = None, *, lines: list[str] | None = None,
                  expected_text: Any = None, expected_lines: Any = None,
                  strip_ansi_escape_sequences: bool = True, strict: bool = False) -> bool:
    """Whether the output (`text` or `lines`) matches the expectation (`expected_text` or
    `expected_lines`, as text.py takes them); lines are joined, or text split, as needed."""
    if (text is None) == (lines is None):
        raise ValueError("Either lines or text, but not both, must be specified")
    if (expected_text is None) == (expected_lines is None):
        raise ValueError("Either expected lines or text, but not both, must be specified")
    clean = remove_ansi_escape_sequences if strip_ansi_escape_sequences else (lambda t: t)
    if expected_text is not None:
        whole = text if text is not None else "\n".join(lines or [])
        return build_text_match(expected_text, strict=strict)(clean(whole)) is not None
    rows = lines if lines is not None else (text or "").splitlines()
    return build_line_match(expected_lines, strict=strict)([clean(r) for r in rows]) \
        is not None
