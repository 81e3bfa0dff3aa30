"""launch_testing_ros.tools.output: basic_output_filter, which also drops the lines an RMW
implementation prints (its `rmw_output_prefixes` and `rmw_output_patterns` resources in the
package index, as ROS 2 keeps them; launcher's graph prints none of its own)."""

from __future__ import annotations

from collections.abc import Callable

from launcher.compat.testing.tools.output import rmw_output_filter as get_rmw_output_filter


def basic_output_filter(filtered_prefixes: list[str] | None = None,
                        filtered_patterns: list[str] | None = None,
                        filtered_rmw_implementation: str | None = None
                        ) -> Callable[[str], str]:
    """launch_testing's basic_output_filter, plus `filtered_rmw_implementation`'s lines."""
    from launch_testing.tools import output

    prefixes = output.get_default_filtered_prefixes() if filtered_prefixes is None \
        else list(filtered_prefixes)
    patterns = output.get_default_filtered_patterns() if filtered_patterns is None \
        else list(filtered_patterns)
    if filtered_rmw_implementation:
        prefixes += get_rmw_output_filter(filtered_rmw_implementation, "prefixes")
        patterns += get_rmw_output_filter(filtered_rmw_implementation, "patterns")
    return output.basic_output_filter(prefixes, patterns)


__all__ = ["basic_output_filter", "get_rmw_output_filter"]
