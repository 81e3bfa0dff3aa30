"""`launcher param dump`: all of a node's parameters, as a params file."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.cli.param import client


def add_arguments(parser: argparse.ArgumentParser) -> None:
    client.add_node_argument(parser)
    client.add_timeout_option(parser)


def run(args: argparse.Namespace) -> int:
    """As `ros2 param dump NODE`: `/NODE: {ros__parameters: {…}}` on stdout, dotted names
    nested."""
    import yaml

    names = list(client.call_parameters(args, params.LIST, "list_parameters", {}).result.names)
    values = client.call_parameters(args, params.GET, "get_parameters", {"names": names}).values
    tree = params.nested((name, params.from_message(value))
                         for name, value in zip(names, values, strict=True))
    print(yaml.safe_dump({args.node: {"ros__parameters": tree}}, sort_keys=True), end="")
    return 0
