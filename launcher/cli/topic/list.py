"""`launcher topic list`: the topics on the bus."""

from __future__ import annotations

import argparse

from launcher.bus import graph
from launcher.bus.names import hidden
from launcher.bus.session import open_session
from launcher.cli.graph_options import (
    add_hidden_option,
    add_sim_option,
    add_types_option,
    space_of,
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_types_option(parser, "topic's message")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="published and subscribed topics, with their types and counts")
    add_hidden_option(parser, "topics")
    parser.add_argument("-c", "--count-topics", action="store_true",
                        help="how many topics there are")
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    session = open_session("client")
    topics = sorted(graph.topics(session, space_of(args)).items())
    session.close()
    if not args.include_hidden_topics:
        topics = [(name, info) for name, info in topics if not hidden(name)]
    if args.count_topics:
        print(len(topics))
        return 0
    if args.verbose:  # as `ros2 topic list -v`
        for title, side, noun in (("Published topics:", "publishers", "publisher"),
                                  ("Subscribed topics:", "subscribers", "subscriber")):
            print(title)
            for name, info in topics:
                count = len(getattr(info, side))
                if count:
                    print(f" * {name} [{', '.join(sorted(info.types))}] {count} "
                          f"{noun}{'' if count == 1 else 's'}")
            print()
        return 0
    for name, info in topics:
        print(f"{name} [{', '.join(sorted(info.types))}]" if args.show_types else name)
    return 0
