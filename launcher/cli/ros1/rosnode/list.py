"""`rosnode list`: list active nodes."""

from __future__ import annotations

import argparse

from launcher.bus.names import expand
from launcher.cli.ros1.rosnode.lookup import graph_entities, node_names


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-a", "--all", action="store_true", help="all names (hidden too)")
    parser.add_argument("namespace", nargs="?", help="only nodes below this namespace")


def run(args: argparse.Namespace) -> int:
    below = expand(args.namespace).rstrip("/") + "/" if args.namespace else "/"
    for name in node_names(graph_entities(), args.all):
        if name.startswith(below):
            print(name)
    return 0
