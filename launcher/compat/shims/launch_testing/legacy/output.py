"""launch_testing.legacy.output (launcher.compat.testing)."""

from launcher.compat.testing.legacy.output import (
    create_output_lines_filter,
    create_output_lines_test,
    create_output_regex_test,
    create_output_test_from_file,
    get_default_filtered_patterns,
    get_default_filtered_prefixes,
    get_rmw_output_filter,
)

__all__ = [
    "create_output_lines_filter", "create_output_lines_test", "create_output_regex_test",
    "create_output_test_from_file", "get_default_filtered_patterns",
    "get_default_filtered_prefixes", "get_rmw_output_filter"
]
