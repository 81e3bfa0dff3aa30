"""`launcher pkg list`: every package, with where it is."""

from __future__ import annotations

import argparse

from launcher.cli.workspace import load_index


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--names", action="store_true",
                        help="the names alone, as `ros2 pkg list` prints them")


def run(args: argparse.Namespace) -> int:
    for package in sorted(load_index(), key=lambda p: p.name):
        print(package.name if args.names else
              f"{package.name:30} {package.origin:9} {package.path}")
    return 0
