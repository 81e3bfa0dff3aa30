"""`rostopic info`: print information about active topic."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import expand
from launcher.cli.ros1.rostopic.lookup import published_topic, topic_table


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic")


def run(args: argparse.Namespace) -> int:
    topic = expand(args.topic)
    info = published_topic(topic, topic_table())
    print(f"Type: {', '.join(ros1_spelling(t) for t in sorted(info.types))}\n")
    for title, endpoints in (("Publishers", info.publishers),
                             ("Subscribers", info.subscribers)):
        print(f"{title}: ")
        names = sorted({e.node_fqn for e in endpoints if not e.node.startswith("_")})
        for name in names:
            print(f" * {name}")
        if not names:
            print(" None")
        print()
    return 0
