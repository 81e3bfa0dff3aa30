"""roslaunch.arg_dump: the arguments the launch files declare, as `roslaunch --ros-args`
lists them: name → (doc, default), for the arguments of the files themselves (not of the
files they include), those with a fixed value left out."""

from __future__ import annotations

from typing import Any

from launcher.errors import LaunchError
from roslaunch.config import load_config_default  # noqa: F401 (roslaunch.arg_dump has it)
from roslaunch.core import RLException


def get_args(roslaunch_files: list[str]) -> dict[str, tuple[str | None, str | None]]:
    """{argument: (its doc, its default: None when it must be given)} of the files."""
    from pathlib import Path

    from launcher.description.actions.arguments import DeclareLaunchArgument
    from launcher.description.actions.include import IncludeLaunchDescription
    from launcher.frontend.loader import load_file

    found: dict[str, tuple[str | None, str | None]] = {}
    try:
        pending = [load_file(Path(f)) for f in roslaunch_files]
    except LaunchError as exc:
        raise RLException(str(exc)) from None
    while pending:
        item = pending.pop(0)
        if isinstance(item, DeclareLaunchArgument):
            found.setdefault(item.name, (item.description or None, _text(item.default_value)))
        elif not isinstance(item, IncludeLaunchDescription):
            pending[:0] = list(item.sub_actions() or []) if hasattr(item, "sub_actions") \
                else list(getattr(item, "actions", []))
    return found


def _text(value: Any) -> str | None:
    """A default as written (its substitutions shown as `$(…)`), None for none."""
    if value is None:
        return None
    return "".join(getattr(part, "text", None) or str(part) for part in value)


def dump_args(roslaunch_files: list[str]) -> None:
    """Print the files' arguments, as `roslaunch --ros-args` does."""
    args = get_args(roslaunch_files)
    if not args:
        print("No arguments.")
        return
    required = sorted(name for name, (_, default) in args.items() if default is None)
    optional = sorted(name for name, (_, default) in args.items() if default is not None)
    if required:
        print("Required Arguments:")
    for name in required:
        print(f"  {name}: {args[name][0] or 'undocumented'}")
    if optional:
        print("Optional Arguments:")
    for name in optional:
        doc, default = args[name]
        print(f"  {name} (default \"{default}\"): {doc or 'undocumented'}")
