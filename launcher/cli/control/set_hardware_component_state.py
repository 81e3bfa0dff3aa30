"""`launcher control set_hardware_component_state`: a hardware component's state."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_state_arguments, on_manager
from launcher.errors import LaunchError
from launcher.lifecycle import STATES
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_state_arguments(parser, "hardware_component_name", "the hardware component")


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    make = manager.node.message
    response = manager.call("set_hardware_component_state",
                            name=args.hardware_component_name,
                            target_state=make("lifecycle_msgs/msg/State",
                                              id=STATES[args.state], label=args.state))
    if not response.ok:
        raise LaunchError(f"Error setting {args.hardware_component_name} to {args.state}, "
                          f"check controller_manager logs")
    print(f"Successfully set {args.hardware_component_name} to state {args.state}")
    return 0
