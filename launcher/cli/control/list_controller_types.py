"""`launcher control list_controller_types`: the controller types the manager can load."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_manager_option, with_manager
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_manager_option(parser)


def run(args: argparse.Namespace) -> int:
    def work(manager: Manager) -> int:
        response = manager.call("list_controller_types")
        for type_name, base in zip(response.types, response.base_classes, strict=True):
            print(f"{type_name:70s} {base}")
        return 0
    return with_manager(args, work)
