"""`rosnode list | info | ping | kill`, as ROS 1's rosnode prints them. A node answers a
ping through its liveliness on the graph (there is no XML-RPC server to ask); `kill` asks
each node, on a key of launcher's own beside the graph, to shut down, and it ends as on
Ctrl-C (rospy's is_shutdown, rclpy's shutdown, the launch's supervision)."""

from __future__ import annotations

import argparse
import time

from launcher.arguments import Parser
from launcher.bus import graph, keys
from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import expand
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean

RULE = "-" * 80


def parser(prog: str = "rosnode") -> Parser:
    p = Parser(prog=prog, description="rosnode is a command-line tool for printing "
                                      "information about ROS Nodes.")
    verbs = p.add_subparsers(dest="verb", metavar="COMMAND", required=True)
    listing = verbs.add_parser("list", help="list active nodes")
    listing.add_argument("-a", "--all", action="store_true", help="all names (hidden too)")
    listing.add_argument("namespace", nargs="?", help="only nodes below this namespace")
    listing.set_defaults(run=run_list)
    info = verbs.add_parser("info", help="print information about node")
    info.add_argument("nodes", nargs="+", metavar="node", help="the nodes")
    info.set_defaults(run=run_info)
    ping = verbs.add_parser("ping", help="test connectivity to node")
    ping.add_argument("node", nargs="?", help="the node")
    ping.add_argument("-a", "--all", action="store_true", help="ping all nodes")
    ping.add_argument("-c", dest="count", type=int, default=0, metavar="COUNT",
                      help="number of pings to send (default: until Ctrl-C)")
    ping.set_defaults(run=run_ping)
    kill = verbs.add_parser("kill", help="kill a running node")
    kill.add_argument("nodes", nargs="*", metavar="node", help="the nodes")
    kill.add_argument("-a", "--all", action="store_true", help="kill all nodes")
    kill.set_defaults(run=run_kill)
    return p


def main(argv: list[str], prog: str = "rosnode") -> int:
    args = parser(prog).parse_args_strictly(argv)
    return int(args.run(args) or 0)


def _entities() -> list[keys.Entity]:
    session = open_session("client")
    try:
        return graph.entities(session)
    finally:
        session.close()


def _names(entities: list[keys.Entity], hidden: bool = False) -> list[str]:
    return sorted({e.node_fqn for e in entities if hidden or not e.node.startswith("_")})


def _known(name: str, entities: list[keys.Entity]) -> str:
    name = expand(name)
    names = _names(entities, hidden=True)
    if name not in names:
        raise LaunchError(f"Unknown node [{name}]{did_you_mean(name, names)}")
    return name


def run_list(args: argparse.Namespace) -> int:
    below = expand(args.namespace).rstrip("/") + "/" if args.namespace else "/"
    for name in _names(_entities(), args.all):
        if name.startswith(below):
            print(name)
    return 0


def run_info(args: argparse.Namespace) -> int:
    entities = _entities()
    for wanted in args.nodes:
        name = _known(wanted, entities)
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


def run_ping(args: argparse.Namespace) -> int:
    if not args.node and not args.all:
        raise LaunchError("Please enter a node to ping (or -a for all)")
    entities = _entities()
    names = _names(entities) if args.all else [_known(args.node, entities)]
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


def run_kill(args: argparse.Namespace) -> int:
    """As rosnode kill: each node is asked to shut down (it ends as on Ctrl-C)."""
    from launcher.bus import keys

    if not args.nodes and not args.all:
        raise LaunchError("Please specify the nodes to kill (or -a for all)")
    entities = _entities()
    names = _names(entities) if args.all else [_known(n, entities) for n in args.nodes]
    nodes = {e.node_fqn: e for e in entities if e.kind == keys.NODE}
    session = open_session("client")
    failed = []
    try:
        for name in names:
            node = nodes.get(name)
            print(f"killing {name}", flush=True)
            answered = node is not None and any(
                reply.ok is not None for reply in session.get(
                    keys.shutdown_key(keys.DOMAIN, node.zid, node.node_id), timeout=3.0))
            if not answered:
                failed.append(name)
    finally:
        session.close()
    if failed:
        raise LaunchError(f"ERROR: could not kill {', '.join(failed)}: no answer (a node of "
                          "another ROS, or an older launcher's)")
    print("killed")
    return 0
