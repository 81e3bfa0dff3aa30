"""`launcher rosparam set`: set a parameter (the value is read as YAML)."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.cli import positive_number
from launcher.cli.rosparam.server import read_file, resolve, with_server
from launcher.errors import UsageError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-t", "--textfile", metavar="FILE",
                        help="the value is this file's text")
    parser.add_argument("name", help="the parameter")
    parser.add_argument("value", nargs="?", help="its value, read as YAML (or -t FILE)")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the server's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    if args.textfile is not None:
        if args.value is not None:
            raise UsageError("give either a value or --textfile, not both")
        value: Any = read_file(args.textfile)
    elif args.value is None:
        raise UsageError("rosparam set needs a value (or --textfile FILE)")
    else:
        value = _parse(args.value, "the value")
    with_server(args, lambda s: s.set(resolve(args.name), value))
    return 0


def _parse(text: str, where: str) -> Any:
    """YAML, as rosparam reads a value; an empty one is the empty string."""
    import yaml

    if text == "":
        return ""
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        at = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        raise UsageError(f"{where} is not valid YAML{at}: "
                         f"{getattr(exc, 'problem', None) or exc}") from None
