"""`launcher control list_controller_types`: the controller types the manager can load."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_manager_option, on_manager
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_manager_option(parser)


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    response = manager.call("list_controller_types")
    for type_name, base in zip(response.types, response.base_classes, strict=True):
        print(f"{type_name:70s} {base}")
    return 0
