"""`launcher topic info`: type and endpoints of a topic."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.bus import graph
from launcher.bus.qos import QoS
from launcher.bus.session import open_session
from launcher.cli import completion
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.topic.lookup import topic_name
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="each publisher and subscription: node, type, QoS")
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    """As `ros2 topic info [-v]`: the type, the counts, and with -v each endpoint with its QoS
    in ros2's layout."""
    session = open_session("client")
    topic = topic_name(args.topic)
    info = graph.topics(session, space_of(args)).get(topic)
    session.close()
    if info is None:
        raise LaunchError(f"unknown topic '{topic}'")
    print(f"Type: {', '.join(sorted(info.types))}")
    for title, endpoints in (("Publisher", info.publishers),
                             ("Subscription", info.subscribers)):
        if args.verbose:
            print()
        print(f"{title} count: {len(endpoints)}")
        if args.verbose:
            for entity in sorted(endpoints, key=lambda e: e.node_fqn):
                print()
                print(endpoint_lines(entity, title.upper()))
    return 0


def endpoint_lines(entity: Any, kind: str) -> str:
    """One endpoint as `ros2 topic info -v` prints it."""
    qos = QoS.from_key(entity.qos)
    lines = [f"Node name: {entity.node}", f"Node namespace: {entity.namespace or '/'}",
             f"Topic type: {entity.type_name}", f"Topic type hash: {entity.type_hash}",
             f"Endpoint type: {kind}", f"GID: {entity.zid}.{entity.node_id}.{entity.entity_id}",
             "QoS profile:"]
    if qos is None:
        return "\n".join([*lines, "  (not announced)"])
    return "\n".join([
        *lines,
        f"  Reliability: {qos.reliability_name}",
        f"  History (Depth): KEEP_LAST ({qos.depth})",
        f"  Durability: {qos.durability_name}",
        "  Lifespan: Infinite", "  Deadline: Infinite", "  Liveliness: AUTOMATIC",
        "  Liveliness lease duration: Infinite"])
