"""launch_testing.parse_arguments: `name:=value` words into the launch's arguments."""

from __future__ import annotations

from collections.abc import ItemsView, Iterable


def parse_launch_arguments(launch_arguments: Iterable[str]) -> ItemsView[str, str]:
    """The (name, value) pairs of `launch_arguments`; the last of a name wins."""
    parsed: dict[str, str] = {}
    for argument in launch_arguments:
        count = argument.count(":=")
        if count == 0 or argument.startswith(":=") or (count == 1 and argument.endswith(":=")):
            raise RuntimeError(f"malformed launch argument '{argument}', expected format "
                               "'<name>:=<value>'")
        name, value = argument.split(":=", maxsplit=1)
        parsed[name] = value
    return parsed.items()
