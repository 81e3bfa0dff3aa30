"""`launcher param set`: set one parameter (the value is read as YAML)."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.bus.ros_args import typed
from launcher.cli import completion, positive_number
from launcher.cli.param.client import call_parameters, parameter_message


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    parser.add_argument("name", help="the parameter")
    parser.add_argument("value", help="its new value, read as YAML")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the node's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    response = call_parameters(args, params.SET, "set_parameters",
                               {"parameters": [parameter_message(args.name, typed(args.value))]})
    if response.results[0].successful:
        print("Set parameter successful")
        return 0
    print(f"Setting parameter failed: {response.results[0].reason}")
    return 1
