"""`launcher param get`: one parameter's value."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.cli.param import client


def add_arguments(parser: argparse.ArgumentParser) -> None:
    client.add_node_argument(parser)
    parser.add_argument("name", help="the parameter")
    client.add_timeout_option(parser)


def run(args: argparse.Namespace) -> int:
    response = client.call_parameters(args, params.GET, "get_parameters", {"names": [args.name]})
    print(params.describe(params.from_message(response.values[0])))
    return 0
