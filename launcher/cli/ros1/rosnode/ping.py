"""`rosnode ping`: test connectivity to node."""

from __future__ import annotations

import argparse
import time

from launcher.bus import graph
from launcher.bus.session import open_session
from launcher.cli.ros1.rosnode.lookup import graph_entities, known_node, node_names
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", nargs="?", help="the node")
    parser.add_argument("-a", "--all", action="store_true", help="ping all nodes")
    parser.add_argument("-c", dest="count", type=int, default=0, metavar="COUNT",
                        help="number of pings to send (default: until Ctrl-C)")


def run(args: argparse.Namespace) -> int:
    if not args.node and not args.all:
        raise LaunchError("Please enter a node to ping (or -a for all)")
    entities = graph_entities()
    names = node_names(entities) if args.all else [known_node(args.node, entities)]
    session = open_session("client")
    sent = 0
    try:
        while True:
            for name in names:
                if sent == 0:
                    print(f"rosnode: node is [{name}]")
                    print(f"pinging {name} with a timeout of 3.0s")
                start = time.monotonic()
                alive = any(e.node_fqn == name for e in graph.entities(session, timeout=3.0))
                took = (time.monotonic() - start) * 1000.0
                if not alive:
                    raise LaunchError(f"connection to [{name}] timed out")
                print(f"reply from {name}\ttime={took:.6f}ms", flush=True)
            sent += 1
            if args.all or (args.count and sent >= args.count):
                return 0
            time.sleep(1.0)
    except KeyboardInterrupt:
        return 0
    finally:
        session.close()
