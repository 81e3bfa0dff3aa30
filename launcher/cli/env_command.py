"""`launcher env [--shell sh|bash|zsh|json]`: the workspace's hooks, for a shell."""

from __future__ import annotations

import argparse
import json
import os
import shlex

from launcher import compat
from launcher.cli.workspace import hooked_environment, load_index


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = ("Print the changes that every package's environment hooks make, as "
                          "commands for a shell (eval \"$(launcher env)\") or as JSON.")
    parser.add_argument("--shell", choices=("sh", "bash", "zsh", "json"), default="sh",
                        help="the form to print: shell commands (default sh) or JSON")
    parser.add_argument("--zenoh", action="store_true",
                        help="instead, the settings that put another Zenoh program on the graph "
                        "(rmw_zenoh's ZENOH_SESSION_CONFIG_URI)")


def changes(before: dict[str, str], after: dict[str, str]) -> dict[str, str | None]:
    names = sorted(set(before) | set(after))
    return {n: after.get(n) for n in names if before.get(n) != after.get(n)}


def run(args: argparse.Namespace) -> int:
    if args.zenoh:
        return zenoh_settings(args.shell)
    before = dict(os.environ)
    after = hooked_environment(load_index(), before)
    compat.node_apis_for_shell(after)
    if args.shell != "json":  # the shell gets `ros2`, `gz`, `roslaunch`, … (last on PATH)
        compat.commands_for_shell(after)
    diff = changes(before, after)
    if args.shell == "json":
        print(json.dumps(diff, indent=2, sort_keys=True))
        return 0
    for name, value in diff.items():
        print(f"unset {name}" if value is None else f"export {name}={shlex.quote(value)}")
    return 0


def zenoh_settings(shell: str) -> int:
    """Write the graph's Zenoh session config (0600: it holds the credentials) next to its
    socket and print the variable that points a real rmw_zenoh node (or any Zenoh program
    that reads it) there."""
    from launcher.bus.session import write_session_config

    path = write_session_config()
    if shell == "json":
        print(json.dumps({"ZENOH_SESSION_CONFIG_URI": str(path)}, indent=2))
    else:
        print(f"export ZENOH_SESSION_CONFIG_URI={shlex.quote(str(path))}")
    return 0
