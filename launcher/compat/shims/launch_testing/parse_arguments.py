"""launch_testing.parse_arguments (launcher.compat.testing)."""

from launcher.compat.testing.parse_arguments import parse_launch_arguments

__all__ = ["parse_launch_arguments"]
