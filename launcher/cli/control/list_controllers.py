"""`launcher control list_controllers`: the loaded controllers, their type and state."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_manager_option, on_manager
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    for flag, text in (("--claimed-interfaces", "each one's claimed interfaces"),
                       ("--required-state-interfaces", "the state interfaces each needs"),
                       ("--required-command-interfaces", "the command interfaces each needs"),
                       ("--chained-interfaces", "the interfaces each is chained to"),
                       ("--reference-interfaces", "the references each exports (deprecated "
                                                  "in ROS 2: --exported-interfaces)"),
                       ("--exported-interfaces", "the state and reference interfaces each "
                                                 "exports")):
        parser.add_argument(flag, action="store_true", help=text)
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="update rate and every interface list")
    add_manager_option(parser)


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    controllers = manager.call("list_controllers").controller
    if not controllers:
        print("No controllers are currently loaded!")
        return 0
    name_w = max(len(c.name) for c in controllers)
    type_w = max(len(c.type) for c in controllers)
    state_w = max(len(c.state) for c in controllers)
    for c in controllers:
        print(f"{c.name:<{name_w}} {c.type:<{type_w}}  {c.state:<{state_w}}")
        if args.verbose:
            print(f"\tupdate_rate: {c.update_rate} Hz")
            print(f"\tis_async: {c.is_async}")
        for flag, title, values in (
                (args.claimed_interfaces, "claimed interfaces", c.claimed_interfaces),
                (args.required_command_interfaces, "required command interfaces",
                 c.required_command_interfaces),
                (args.required_state_interfaces, "required state interfaces",
                 c.required_state_interfaces),
                (args.chained_interfaces, "chained to interfaces", []),
                (args.reference_interfaces or args.exported_interfaces,
                 "exported reference interfaces", c.reference_interfaces),
                (args.reference_interfaces or args.exported_interfaces,
                 "exported state interfaces", c.exported_state_interfaces)):
            if flag or args.verbose:
                print(f"\t{title}:")
                for value in values:
                    print(f"\t\t{value}")
    return 0
