"""`launcher bag convert`: a ROS 1 bag (.bag) to a rosbag2 bag (MCAP), or back."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("source", metavar="IN", help="a .bag file, or a rosbag2 bag folder")
    parser.add_argument("target", metavar="OUT",
                        help="the new rosbag2 folder, or the new .bag file")


def run(args: argparse.Namespace) -> int:
    from launcher.bus import bag1

    bag1.convert(Path(args.source), Path(args.target))
    print(f"wrote {args.target}")
    return 0
