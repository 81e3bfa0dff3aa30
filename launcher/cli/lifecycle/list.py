"""`launcher lifecycle list`: the transitions a node offers now."""

from __future__ import annotations

import argparse

from launcher.cli.lifecycle.client import (
    available_transitions,
    checked_node,
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node (/lc_talker)")
    parser.add_argument("-a", "--all", action="store_true", help="every transition")


def run(args: argparse.Namespace) -> int:
    node = checked_node(args.node)
    for d in available_transitions(node, args.all):
        print(f"- {d.transition.label} [{d.transition.id}]\n"
              f"\tStart: {d.start_state.label}\n\tGoal: {d.goal_state.label}")
    return 0
