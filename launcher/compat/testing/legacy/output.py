"""launch_testing.legacy.output: the output tests of LaunchTestService.add_output_test. An
output test is (buffer, collate, match, patterns): each piece of output is collated into the
buffer, and a pattern is done once `match(buffer, pattern)`. Output here is bytes."""

from __future__ import annotations

import io
import os
import re
from collections.abc import Callable
from typing import Any

from launcher.compat.testing.tools.output import rmw_output_filter

OutputTest = tuple[io.BytesIO, Callable[[io.BytesIO, bytes], io.BytesIO],
                   Callable[[io.BytesIO, Any], bool], list[Any]]


def get_default_filtered_prefixes() -> list[bytes]:
    return [b"pid", b"rc"]


def get_default_filtered_patterns() -> list[bytes]:
    return []


def get_rmw_output_filter(rmw_implementation: str, filter_type: str) -> list[bytes]:
    """The lines `rmw_implementation` prints that tests ignore (its rmw_output_prefixes or
    rmw_output_patterns resource in the package index), as bytes."""
    return [line.encode() for line in rmw_output_filter(rmw_implementation, filter_type)]


def create_output_lines_filter(filtered_prefixes: list[bytes] | None = None,
                               filtered_patterns: list[bytes] | None = None,
                               filtered_rmw_implementation: str | None = None
                               ) -> Callable[[bytes], bytes]:
    """A filter of output that drops the lines starting with one of `filtered_prefixes`
    (default: b'pid' and b'rc') or matching one of `filtered_patterns`, and the RMW's."""
    prefixes = list(filtered_prefixes or get_default_filtered_prefixes())
    patterns = list(filtered_patterns or get_default_filtered_patterns())
    if filtered_rmw_implementation:
        prefixes += get_rmw_output_filter(filtered_rmw_implementation, "prefixes")
        patterns += get_rmw_output_filter(filtered_rmw_implementation, "patterns")
    compiled = [re.compile(pattern) for pattern in patterns]
    separator = os.linesep.encode("ascii")

    def output_filter(output: bytes) -> bytes:
        kept = [line for line in output.splitlines()
                if not line.startswith(tuple(prefixes)) and not any(p.match(line)
                                                                     for p in compiled)]
        if output.endswith(separator):
            kept.append(separator)
        return separator.join(kept)
    return output_filter


def create_output_lines_test(expected_lines: list[bytes]) -> OutputTest:
    """An output test: each of `expected_lines` is in some line of the output."""
    def collate(output: io.BytesIO, addendum: bytes) -> io.BytesIO:
        output.write(addendum)
        return output

    def match(output: io.BytesIO, pattern: bytes) -> bool:
        return any(pattern in line for line in output.getvalue().splitlines())

    return io.BytesIO(), collate, match, expected_lines


def create_output_regex_test(expected_patterns: list[Any]) -> OutputTest:
    """An output test: each of `expected_patterns` (compiled, of bytes) is found."""
    def collate(output: io.BytesIO, addendum: bytes) -> io.BytesIO:
        output.write(b"\n".join(addendum.splitlines()))
        return output

    def match(output: io.BytesIO, pattern: Any) -> bool:
        return pattern.search(output.getvalue()) is not None

    return io.BytesIO(), collate, match, expected_patterns


def create_output_test_from_file(output_file: str) -> OutputTest:
    """The output test of `output_file`.txt (lines), or else of `output_file`.regex."""
    if os.path.isfile(output_file + ".txt"):
        with open(output_file + ".txt", "rb") as f:
            return create_output_lines_test(f.read().splitlines())
    if os.path.isfile(output_file + ".regex"):
        with open(output_file + ".regex", "rb") as f:
            return create_output_regex_test([re.compile(r) for r in f.read().splitlines()])
    raise RuntimeError(f"could not find output check file: {output_file}")
