"""`launcher control list_hardware_components`: the hardware components."""

from __future__ import annotations

import argparse

from launcher.cli.control.hardware import add_hardware_arguments, availability, command_interface
from launcher.cli.control.manager import on_manager
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_hardware_arguments(parser, verbose="with the state interfaces and data types")


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    for index, c in enumerate(manager.call("list_hardware_components").component):
        print(f"Hardware Component {index + 1}\n\tname: {c.name}\n\ttype: {c.type}")
        print(f"\tplugin name: {c.plugin_name}\n"
              f"\tstate: id={c.state.id} label={c.state.label}\n"
              f"\tread/write rate: {c.rw_rate} Hz\n"
              f"\tis_async: {c.is_async}\n"
              f"\tcommand interfaces")
        for item in c.command_interfaces:
            print(f"\t\t{command_interface(item, args.verbose)}")
        if args.verbose:
            print("\tstate interfaces")
            for item in c.state_interfaces:
                print(f"\t\t{item.name} [{item.data_type}] {availability(item)}")
    return 0
