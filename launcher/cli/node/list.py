"""`launcher node list`: the nodes on the graph, and the host each runs on when they run on
more than one."""

from __future__ import annotations

import argparse

from launcher.bus import graph, keys
from launcher.bus.session import open_session

UNKNOWN = "?"  # the host of a node whose program does not say (not launcher's)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-a", "--all", action="store_true",
                        help="hidden nodes too (names that begin with '_')")
    parser.add_argument("--hosts", action="store_true",
                        help="the host each node runs on, even when all run on one")


def run(args: argparse.Namespace) -> int:
    session = open_session("client")
    try:
        nodes = [e for e in graph.nodes(session) if args.all or not e.node.startswith("_")]
        where = graph.hosts(session)
    finally:
        session.close()
    for line in lines(nodes, where, args.hosts):
        print(line)
    return 0


def lines(nodes: list[keys.Entity], where: dict[str, str], hosts: bool = False) -> list[str]:
    """One line per node, sorted: its name, then `[host]` when the nodes run on more than
    one host (or `hosts`). Two nodes of one name on two hosts are two lines then."""
    placed = sorted({(e.node_fqn, where.get(e.zid, UNKNOWN)) for e in nodes})
    if not hosts and len({host for _, host in placed} - {UNKNOWN}) <= 1:
        return sorted({name for name, _ in placed})
    width = max((len(name) for name, _ in placed), default=0)
    return [f"{name:<{width}}  [{host}]" for name, host in placed]
