"""launch_testing.print_arguments: the launch arguments a test description takes, printed as
`launcher launch --show-args` prints them."""

from __future__ import annotations

from typing import Any


def print_arguments_of_launch_description(*, launch_description: Any) -> None:
    """Print the arguments `launch_description` declares (its includes' too)."""
    from launcher.cli import views
    from launcher.cli.workspace import load_index

    print(views.show_arguments(launch_description, {}, load_index()), end="")
