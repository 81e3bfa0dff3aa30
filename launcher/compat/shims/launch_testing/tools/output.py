"""launch_testing.tools.output (launcher.compat.testing)."""

from launcher.compat.testing.tools.output import (
    basic_output_filter,
    expect_output,
    expected_output_from_file,
    get_default_filtered_patterns,
    get_default_filtered_prefixes,
    remove_ansi_escape_sequences,  # noqa: F401
)
from launcher.compat.testing.tools.text import build_line_match, build_text_match  # noqa: F401

__all__ = [
    "basic_output_filter", "expect_output", "expected_output_from_file",
    "get_default_filtered_patterns", "get_default_filtered_prefixes"
]
