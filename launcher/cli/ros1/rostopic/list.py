"""`rostopic list`: list active topics."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import below
from launcher.cli.ros1.rostopic.lookup import topic_table


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="list full details about each topic")
    parser.add_argument("namespace", nargs="?", help="only topics below this namespace")


def run(args: argparse.Namespace) -> int:
    prefix = below(args.namespace)
    topics = {n: i for n, i in sorted(topic_table().items()) if n.startswith(prefix)}
    if not args.verbose:
        for name in topics:
            print(name)
        return 0
    for title, side, noun in (("Published topics:", "publishers", "publisher"),
                              ("Subscribed topics:", "subscribers", "subscriber")):
        print(title)
        for name, info in topics.items():
            count = len(getattr(info, side))
            if count:
                kinds = ", ".join(ros1_spelling(t) for t in sorted(info.types))
                print(f" * {name} [{kinds}] {count} {noun}{'' if count == 1 else 's'}")
        print()
    return 0
