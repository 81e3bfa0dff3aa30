"""`rosnode info`: print information about node."""

from __future__ import annotations

import argparse

from launcher.bus import keys
from launcher.bus.interfaces import ros1_spelling
from launcher.cli.ros1.rosnode.lookup import graph_entities, known_node

RULE = "-" * 80


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("nodes", nargs="+", metavar="node", help="the nodes")


def run(args: argparse.Namespace) -> int:
    entities = graph_entities()
    for wanted in args.nodes:
        name = known_node(wanted, entities)
        mine = [e for e in entities if e.node_fqn == name]
        print(RULE)
        print(f"Node [{name}]")
        for kind, title in ((keys.PUBLISHER, "Publications"),
                            (keys.SUBSCRIPTION, "Subscriptions"), (keys.SERVICE, "Services")):
            found = sorted({(e.topic, e.type_name) for e in mine if e.kind == kind})
            if not found:
                print(f"{title}: None\n")
                continue
            print(f"{title}: ")
            for topic, type_name in found:
                print(f" * {topic}" if kind == keys.SERVICE else
                      f" * {topic} [{ros1_spelling(type_name)}]")
            print()
        print()
    return 0
