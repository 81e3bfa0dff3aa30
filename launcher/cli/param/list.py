"""`launcher param list`: a node's parameter names."""

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
    response = call_parameters(args, params.LIST, "list_parameters", {})
    print(f"{args.node}:")
    for name in response.result.names:
        print(f"  {name}")
    return 0
