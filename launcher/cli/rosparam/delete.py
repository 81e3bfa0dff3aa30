"""`launcher rosparam delete`: delete a parameter and everything below it."""

from __future__ import annotations

import argparse

from launcher.cli import positive_number
from launcher.cli.rosparam.server import resolve, with_server


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the parameter, with all below it")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the server's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    with_server(args, lambda s: s.delete(resolve(args.name)))
    return 0
