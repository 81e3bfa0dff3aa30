"""`launcher topic find`: the topics of a type."""

from __future__ import annotations

import argparse

from launcher.bus import graph
from launcher.bus.session import open_session
from launcher.cli.graph_options import add_sim_option, space_of


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("type", help="a message type (std_msgs/msg/String)")
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    session = open_session("client")
    topics = graph.topics(session, space_of(args))
    session.close()
    for name, info in sorted(topics.items()):
        if args.type in info.types:
            print(name)
    return 0
