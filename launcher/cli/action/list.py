"""`launcher action list`: the actions on the graph."""

from __future__ import annotations

import argparse

from launcher.cli.action.lookup import actions_served, send_goal_endpoints


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-t", "--show-types", action="store_true",
                        help="each action's type too")
    parser.add_argument("-c", "--count-actions", action="store_true",
                        help="only how many there are")


def run(args: argparse.Namespace) -> int:
    actions = actions_served(send_goal_endpoints())
    if args.count_actions:
        print(len(actions))
        return 0
    for name in sorted(actions):
        print(f"{name} [{', '.join(sorted(actions[name]))}]" if args.show_types else name)
    return 0
