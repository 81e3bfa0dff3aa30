"""`rosnode kill`: kill a running node."""

from __future__ import annotations

import argparse

from launcher.bus.session import open_session
from launcher.cli.ros1.rosnode.lookup import graph_entities, known_node, node_names
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("nodes", nargs="*", metavar="node", help="the nodes")
    parser.add_argument("-a", "--all", action="store_true", help="kill all nodes")


def run(args: argparse.Namespace) -> int:
    """As rosnode kill: each node is asked to shut down (it ends as on Ctrl-C)."""
    from launcher.bus import keys

    if not args.nodes and not args.all:
        raise LaunchError("Please specify the nodes to kill (or -a for all)")
    entities = graph_entities()
    names = node_names(entities) if args.all else [known_node(n, entities) for n in args.nodes]
    nodes = {e.node_fqn: e for e in entities if e.kind == keys.NODE}
    session = open_session("client")
    failed = []
    try:
        for name in names:
            node = nodes.get(name)
            print(f"killing {name}", flush=True)
            answered = node is not None and any(
                reply.ok is not None for reply in session.get(
                    keys.shutdown_key(keys.domain(), node.zid, node.node_id), timeout=3.0))
            if not answered:
                failed.append(name)
    finally:
        session.close()
    if failed:
        raise LaunchError(f"ERROR: could not kill {', '.join(failed)}: no answer (a node of "
                          "another ROS, or an older launcher's)")
    print("killed")
    return 0
