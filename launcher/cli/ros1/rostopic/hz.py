"""`rostopic hz`: display publishing rate of topic, as `launcher topic hz` measures it."""

from __future__ import annotations

import argparse

from launcher.bus.names import expand
from launcher.cli.topic import hz


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="+", metavar="topic", help="the topics")
    parser.add_argument("-w", "--window", type=int, default=None, metavar="WINDOW",
                        help="window size, in # of messages, for calculating rate")


def run(args: argparse.Namespace) -> int:
    for topic in args.topics:
        print(f"subscribed to [{expand(topic)}]", flush=True)
    return hz.run(argparse.Namespace(topics=[expand(t) for t in args.topics], wall_time=False,
                                     window=args.window or 10000, sim=False))
