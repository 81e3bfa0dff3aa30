"""`launcher node info`: a node's publishers, subscriptions and services."""

from __future__ import annotations

import argparse

from launcher.bus import graph, keys
from launcher.bus.session import open_session
from launcher.cli import completion
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the node's full name").completer = \
        completion.nodes  # type: ignore[attr-defined]


def run(args: argparse.Namespace) -> int:
    session = open_session("client")
    mine = [e for e in graph.entities(session) if e.node_fqn == args.name]
    session.close()
    if not mine:
        raise LaunchError(f"no node '{args.name}' on the bus")
    print(args.name)
    for kind, title in ((keys.SUBSCRIPTION, "Subscribers"), (keys.PUBLISHER, "Publishers"),
                        (keys.SERVICE, "Service Servers"), (keys.CLIENT, "Service Clients")):
        print(f"  {title}:")
        for entity in sorted((e for e in mine if e.kind == kind), key=lambda e: e.topic):
            print(f"    {entity.topic}: {entity.type_name}")
    return 0
