"""`rosnode list`: list active nodes."""

from __future__ import annotations

import argparse

from launcher.bus.names import below
from launcher.cli.ros1.rosnode.lookup import graph_entities, node_names


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-a", "--all", action="store_true", help="all names (hidden too)")
    parser.add_argument("namespace", nargs="?", help="only nodes below this namespace")


def run(args: argparse.Namespace) -> int:
    prefix = below(args.namespace)
    for name in node_names(graph_entities(), args.all):
        if name.startswith(prefix):
            print(name)
    return 0
