"""launch_testing.tools.text (launcher.compat.testing)."""

from launcher.compat.testing.tools.text import (
    build_line_match,
    build_text_match,
    normalize_lineseps,
)

__all__ = ["build_line_match", "build_text_match", "normalize_lineseps"]
