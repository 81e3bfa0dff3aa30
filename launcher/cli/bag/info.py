"""`launcher bag info`: what a bag holds."""

from __future__ import annotations

import argparse

from launcher.bus import bag
from launcher.cli.bag.folder import bag_folder


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("path", metavar="DIR", help="the bag (a folder)")


def run(args: argparse.Namespace) -> int:
    print(bag.describe(bag_folder(args.path)))
    return 0
