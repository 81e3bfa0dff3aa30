"""`launcher rosparam list`: the parameter names (below a namespace)."""

from __future__ import annotations

import argparse

from launcher.cli import positive_number
from launcher.cli.rosparam.server import resolve, with_server


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("namespace", nargs="?", default="/", help="list below this name")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the server's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    for name in with_server(args, lambda s: s.names(resolve(args.namespace))):
        print(name)
    return 0
