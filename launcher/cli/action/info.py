"""`launcher action info`: an action's servers and clients."""

from __future__ import annotations

import argparse

from launcher.bus import keys
from launcher.cli.action.lookup import (
    SEND_GOAL,
    action_types,
    send_goal_endpoints,
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the action (/fibonacci)")
    parser.add_argument("-t", "--show-types", action="store_true", help="their types too")
    parser.add_argument("-c", "--count", action="store_true", help="only how many")


def run(args: argparse.Namespace) -> int:
    found = send_goal_endpoints()
    types = action_types(args.name, found)
    mine = [e for e in found if e.topic == args.name + SEND_GOAL]
    print(f"Action: {args.name}")
    for kind, title in ((keys.CLIENT, "Action clients"), (keys.SERVICE, "Action servers")):
        nodes = sorted({e.node_fqn for e in mine if e.kind == kind})
        print(f"{title}: {len(nodes)}")
        if args.count:
            continue
        for node in nodes:
            print(f"    {node} [{', '.join(sorted(types))}]" if args.show_types
                  else f"    {node}")
    return 0
