"""`launcher param delete`: delete parameters (a node refuses it for one declared with a
fixed type)."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.cli.param import client


def add_arguments(parser: argparse.ArgumentParser) -> None:
    client.add_names_arguments(parser)


def run(args: argparse.Namespace) -> int:
    """As `ros2 param delete NODE NAME…`: each result said; exit 1 if one was refused."""
    response = client.call_parameters(args, params.SET, "set_parameters",
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
