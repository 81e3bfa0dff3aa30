"""`rostopic bw`: display bandwidth used by topic, as `launcher topic bw` measures it."""

from __future__ import annotations

import argparse

from launcher.bus.names import expand
from launcher.cli.topic import bw


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="+", metavar="topic", help="the topics")
    parser.add_argument("-w", "--window", type=int, default=None, metavar="WINDOW",
                        help="window size, in # of messages, for calculating rate")


def run(args: argparse.Namespace) -> int:
    return bw.run(argparse.Namespace(topics=[expand(t) for t in args.topics], wall_time=False,
                                     window=args.window or 100, sim=False))
