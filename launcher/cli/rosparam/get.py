"""`launcher rosparam get`: a parameter's value, or a namespace's as YAML."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.cli import positive_number
from launcher.cli.rosparam.server import resolve, with_server, yaml_text


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-p", dest="pretty", action="store_true",
                        help="pretty print (a namespace as indented keys, text as it is)")
    parser.add_argument("name", help="the parameter (or a namespace: all below it)")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the server's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    value = with_server(args, lambda s: s.get(resolve(args.name)))
    if args.pretty and isinstance(value, dict):
        _pretty(value, "")
    elif args.pretty and isinstance(value, str):
        print(value)
    else:
        print(yaml_text(value))
    return 0


def _pretty(value: dict[str, Any], indent: str) -> None:
    """rosparam get -p: keys sorted, dicts indented, text as it is."""
    for key in sorted(value):
        item = value[key]
        if isinstance(item, dict):
            print(f"{indent}{key}:")
            _pretty(item, indent + "  ")
        elif isinstance(item, str) and "\n" in item:
            print(f"{indent}{key}: |")
            for line in item.split("\n"):
                print(f"{indent}  {line}")
        else:
            print(f"{indent}{key}: {item if isinstance(item, str) else yaml_text(item)}")
