"""`rosbag info`: summarize the contents of one bag file."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE.bag", help="the bag")


def run(args: argparse.Namespace) -> int:
    from launcher.bus import bag1

    print(bag1.info(Path(args.file)))
    return 0
