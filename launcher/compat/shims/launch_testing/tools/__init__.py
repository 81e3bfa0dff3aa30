"""launch_testing.tools (launcher.compat.testing)."""

from launcher.compat.testing.tools.output import (
    basic_output_filter,
    expect_output,
    expected_output_from_file,
)
from launcher.compat.testing.tools.process import ProcessProxy, launch_process

__all__ = [
    "ProcessProxy", "basic_output_filter", "expect_output", "expected_output_from_file",
    "launch_process"
]
