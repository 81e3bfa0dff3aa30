"""`launcher param delete`: delete parameters (a node refuses it for one declared with a
fixed type)."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.cli import completion, positive_number
from launcher.cli.param.client import call_parameters


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    parser.add_argument("names", nargs="+", metavar="name", help="the parameters")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the node's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    """As `ros2 param delete NODE NAME…`: each result said; exit 1 if one was refused."""
    response = call_parameters(args, params.SET, "set_parameters",
                               {"parameters": [{"name": n, "value": {"type": params.NOT_SET}}
                                               for n in args.names]})
    failed = 0
    for result in response.results:
        if result.successful:
            print("Deleted parameter successfully")
        else:
            failed += 1
            print(f"Deleting parameter failed: {result.reason}")
    return 1 if failed else 0
