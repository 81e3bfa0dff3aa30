"""`launcher param set`: set one parameter (the value is read as YAML)."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.bus.ros_args import typed
from launcher.cli.param import client


def add_arguments(parser: argparse.ArgumentParser) -> None:
    client.add_node_argument(parser)
    parser.add_argument("name", help="the parameter")
    parser.add_argument("value", help="its new value, read as YAML")
    client.add_timeout_option(parser)


def run(args: argparse.Namespace) -> int:
    message = client.parameter_message(args.name, typed(args.value))
    response = client.call_parameters(args, params.SET, "set_parameters",
                                      {"parameters": [message]})
    if response.results[0].successful:
        print("Set parameter successful")
        return 0
    print(f"Setting parameter failed: {response.results[0].reason}")
    return 1
