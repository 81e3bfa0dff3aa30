"""`launcher param dump`: all of a node's parameters, as a params file."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.cli import completion, positive_number
from launcher.cli.param.client import call_parameters


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the node's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    """As `ros2 param dump NODE`: `/NODE: {ros__parameters: {…}}` on stdout, dotted names
    nested."""
    import yaml

    names = list(call_parameters(args, params.LIST, "list_parameters", {}).result.names)
    values = call_parameters(args, params.GET, "get_parameters", {"names": names}).values
    tree = params.nested((name, params.from_message(value))
                         for name, value in zip(names, values, strict=True))
    print(yaml.safe_dump({args.node: {"ros__parameters": tree}}, sort_keys=True), end="")
    return 0
