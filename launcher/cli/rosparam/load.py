"""`launcher rosparam load`: set the parameters of a YAML file (into a namespace)."""

from __future__ import annotations

import argparse
import sys

from launcher.cli import positive_number
from launcher.cli.rosparam.server import read_file, resolve, with_server
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="a YAML file ('-': stdin)")
    parser.add_argument("namespace", nargs="?", default="/", help="load below this name")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the server's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    import yaml

    from launcher.errors import Location

    text = sys.stdin.read() if args.file == "-" else read_file(args.file)
    try:
        document = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = Location(args.file, mark.line + 1, mark.column + 1) if mark else None
        raise LaunchError(f"not valid YAML: {getattr(exc, 'problem', None) or exc}",
                          where) from None
    space = resolve(args.namespace)
    if isinstance(document, dict):
        values = {f"{space.rstrip('/')}/{key}": value for key, value in document.items()}
        with_server(args, lambda s: s.set_many(values))
    elif document is not None:
        if space == "/":
            raise LaunchError(f"'{args.file}' holds one value, not a map of names; give the "
                              "namespace (its name) to load it into")
        with_server(args, lambda s: s.set(space, document))
    return 0
