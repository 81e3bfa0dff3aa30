"""`launcher param list`: a node's parameter names."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.cli.param import client


def add_arguments(parser: argparse.ArgumentParser) -> None:
    client.add_node_argument(parser)
    client.add_timeout_option(parser)


def run(args: argparse.Namespace) -> int:
    response = client.call_parameters(args, params.LIST, "list_parameters", {})
    print(f"{args.node}:")
    for name in response.result.names:
        print(f"  {name}")
    return 0
