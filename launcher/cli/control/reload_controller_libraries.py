"""`launcher control reload_controller_libraries`: reload the controller libraries."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_manager_option, on_manager
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--force-kill", action="store_true",
                        help="accepted: launcher's controllers are Python classes")
    add_manager_option(parser)


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    manager.call("reload_controller_libraries", force_kill=args.force_kill)
    print("Reload successful")
    return 0
