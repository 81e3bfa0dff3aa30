"""launch_testing.print_arguments (launcher.compat.testing)."""

from launcher.compat.testing.print_arguments import print_arguments_of_launch_description

__all__ = ["print_arguments_of_launch_description"]
