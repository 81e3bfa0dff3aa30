"""`rosbag play`: play back the contents of one bag file."""

from __future__ import annotations

import argparse
from pathlib import Path

from launcher.errors import LaunchError, UsageError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE.bag", help="the bag")
    parser.add_argument("-r", "--rate", type=float, default=1.0, metavar="FACTOR",
                        help="multiply the publish rate by FACTOR")
    parser.add_argument("-l", "--loop", action="store_true", help="loop playback")
    parser.add_argument("--clock", action="store_true", help="publish the clock time")
    parser.add_argument("--topics", nargs="+", metavar="TOPIC", help="topics to play back")
    parser.add_argument("-q", "--quiet", action="store_true", help="suppress console output")


def run(args: argparse.Namespace) -> int:
    from launcher.bus import bag, bag1
    from launcher.bus.node import Node

    path = Path(args.file)
    if args.rate <= 0:
        raise UsageError(f"rosbag play: -r must be above 0, got {args.rate:g}")
    if path.suffix != ".bag" and path.is_dir():
        raise LaunchError(f"'{path}' is a rosbag2 bag: play it with `launcher bag play "
                          f"{path}` (or `ros2 bag play`)")
    holder = bag1.temporary_rosbag2(path)
    node = Node("_rosbag_play", argv=[], parameter_services=False)
    try:
        if not args.quiet:
            print(f"[ INFO] Opening {path}", flush=True)
        sent = bag.play(node, Path(holder.name) / "bag", args.rate, args.loop,
                        topics=args.topics, clock=100.0 if args.clock else None)
    except KeyboardInterrupt:
        sent = -1
    finally:
        node.destroy_node()
        holder.cleanup()
    if sent >= 0 and not args.quiet:
        print("\nDone.")
    return 0
