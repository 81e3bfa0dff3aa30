"""`launcher control list_hardware_interfaces`: the command and state interfaces."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_manager_option, on_manager
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="with each interface's data type")
    add_manager_option(parser)


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    response = manager.call("list_hardware_interfaces")
    print("command interfaces")
    for item in sorted(response.command_interfaces, key=lambda i: i.name):
        kind = f" [{item.data_type}]" if args.verbose else ""
        availability = "[available]" if item.is_available else "[unavailable]"
        claim = "[claimed]" if item.is_claimed else "[unclaimed]"
        print(f"\t{item.name}{kind} {availability} {claim}")
    print("state interfaces")
    for item in sorted(response.state_interfaces, key=lambda i: i.name):
        kind = f" [{item.data_type}]" if args.verbose else ""
        print(f"\t{item.name}{kind}")
    return 0
