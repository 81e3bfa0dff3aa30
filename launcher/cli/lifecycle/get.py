"""`launcher lifecycle get`: a node's state."""

from __future__ import annotations

import argparse

from launcher.cli.lifecycle.client import call_node, checked_node, lifecycle_nodes


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", nargs="?", help="the node (all of them without)")


def run(args: argparse.Namespace) -> int:
    for node in [checked_node(args.node)] if args.node else lifecycle_nodes():
        state = call_node(node, "get_state", "lifecycle_msgs/srv/GetState").current_state
        prefix = f"{node}: " if not args.node else ""
        print(f"{prefix}{state.label} [{state.id}]")
    return 0
