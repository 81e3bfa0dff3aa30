"""`launcher control switch_controllers`: activate and deactivate in one step."""

from __future__ import annotations

import argparse

from launcher.bus.wire import split_time
from launcher.cli.control.manager import add_manager_option, on_manager
from launcher.errors import LaunchError
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--deactivate", nargs="*", default=[], help="controllers to stop")
    parser.add_argument("--activate", nargs="*", default=[], help="controllers to start")
    strictness = parser.add_mutually_exclusive_group()
    strictness.add_argument("--strict", action="store_true",
                            help="all or nothing (the default)")
    strictness.add_argument("--best-effort", action="store_true",
                            help="switch what can be switched")
    parser.add_argument("--activate-asap", action="store_true",
                        help="accepted: a switch always lands between two control cycles")
    parser.add_argument("--switch-timeout", type=float, default=5.0,
                        help="seconds the manager may take to switch (default 5)")
    add_manager_option(parser)


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    sec, nanosec = split_time(args.switch_timeout)
    response = manager.call(
        "switch_controller", activate_controllers=args.activate,
        deactivate_controllers=args.deactivate, strictness=1 if args.best_effort else 2,
        activate_asap=args.activate_asap, timeout=manager.node.message(
            "builtin_interfaces/msg/Duration", sec=sec, nanosec=nanosec))
    if not response.ok:
        raise LaunchError(f"Error switching controllers, check controller_manager logs"
                          f"{': ' + response.message if response.message else ''}")
    print("Successfully switched controllers")
    return 0
