"""`launcher action type`: the type of an action."""

from __future__ import annotations

import argparse

from launcher.cli.action.lookup import (
    action_types,
    send_goal_endpoints,
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the action")


def run(args: argparse.Namespace) -> int:
    for type_name in sorted(action_types(args.name, send_goal_endpoints())):
        print(type_name)
    return 0
