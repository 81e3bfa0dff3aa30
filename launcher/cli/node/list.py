"""`launcher node list`: the nodes on the graph."""

from __future__ import annotations

import argparse

from launcher.bus import graph
from launcher.bus.session import open_session


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-a", "--all", action="store_true",
                        help="hidden nodes too (names that begin with '_')")


def run(args: argparse.Namespace) -> int:
    session = open_session("client")
    for name in sorted({e.node_fqn for e in graph.nodes(session)
                        if args.all or not e.node.startswith("_")}):
        print(name)
    session.close()
    return 0
