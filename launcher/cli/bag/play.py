"""`launcher bag play`: publish a bag's messages again."""

from __future__ import annotations

import argparse

from launcher.bus import bag
from launcher.bus.node import Node
from launcher.cli import positive_number
from launcher.cli.bag.folder import bag_folder
from launcher.errors import UsageError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("path", metavar="DIR", help="the bag (a folder)")
    parser.add_argument("--topics", nargs="+", metavar="TOPIC", help="only these topics")
    parser.add_argument("-r", "--rate", type=positive_number, default=1.0, metavar="FACTOR",
                        help="how many times faster than recorded (default 1)")
    parser.add_argument("-l", "--loop", action="store_true", help="play again from the start, "
                                                                  "until Ctrl-C")
    parser.add_argument("--clock", type=positive_number, nargs="?", const=40.0, default=None,
                        metavar="HZ", help="publish /clock from the bag's time, HZ times a second "
                                           "(default 40)")
    parser.add_argument("-p", "--start-paused", action="store_true",
                        help="start paused; Enter plays and pauses")
    parser.add_argument("--start-offset", type=float, default=0.0, metavar="SECONDS",
                        help="skip this many seconds from the bag's start")


def run(args: argparse.Namespace) -> int:
    folder = bag_folder(args.path)
    if args.start_offset < 0:
        raise UsageError(f"--start-offset: expected seconds ≥ 0, got {args.start_offset:g}")
    node = Node("_launcher_bag_play", argv=[], parameter_services=False)
    try:
        sent = bag.play(node, folder, args.rate, args.loop, topics=args.topics,
                        clock=args.clock, paused=args.start_paused, offset=args.start_offset)
    except KeyboardInterrupt:
        sent = -1
    finally:
        node.destroy_node()
    if sent >= 0:
        print(f"played {sent} messages")
    return 0
