"""`launcher rosparam dump`: a namespace as YAML, to a file (or stdout)."""

from __future__ import annotations

import argparse
import sys

from launcher.cli import positive_number
from launcher.cli.rosparam.server import resolve, with_server, yaml_text
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", nargs="?", help="where to write it (default: stdout)")
    parser.add_argument("namespace", nargs="?", default="/", help="dump below this name")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the server's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    text = yaml_text(with_server(args, lambda s: s.get(resolve(args.namespace)))) + "\n"
    if args.file in (None, "-"):
        sys.stdout.write(text)
        return 0
    try:
        with open(args.file, "w", encoding="utf-8") as handle:
            handle.write(text)
    except OSError as exc:
        raise LaunchError(f"cannot write '{args.file}': {exc.strerror}") from None
    return 0
