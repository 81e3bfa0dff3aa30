"""`launcher control list_hardware_interfaces`: the command and state interfaces."""

from __future__ import annotations

import argparse

from launcher.cli.control.hardware import add_hardware_arguments, command_interface
from launcher.cli.control.manager import on_manager
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_hardware_arguments(parser, verbose="with each interface's data type")


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    response = manager.call("list_hardware_interfaces")
    print("command interfaces")
    for item in sorted(response.command_interfaces, key=lambda i: i.name):
        print(f"\t{command_interface(item, args.verbose)}")
    print("state interfaces")
    for item in sorted(response.state_interfaces, key=lambda i: i.name):
        kind = f" [{item.data_type}]" if args.verbose else ""
        print(f"\t{item.name}{kind}")
    return 0
