"""`launcher control set_controller_state`: configure, activate, deactivate or clean up."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_state_arguments, on_manager, state_of
from launcher.errors import LaunchError
from launcher.nodes.spawner import Manager


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_state_arguments(parser, "controller_name", "the controller")


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    name, target = args.controller_name, args.state
    current = state_of(manager, name)
    if not current:
        raise LaunchError(f"controller {name} does not seem to be loaded")
    if target == "unconfigured":
        if current != "inactive":
            raise LaunchError(f"cannot cleanup {name} from its current state {current}")
        if not manager.call("cleanup_controller", name=name).ok:
            raise LaunchError("Error cleaning up controller, check controller_manager logs")
        print(f"successfully cleaned up {name}")
    elif target == "inactive":
        if current == "unconfigured":
            if not manager.call("configure_controller", name=name).ok:
                raise LaunchError("Error configuring controller, check controller_manager "
                                  "logs")
            print(f"Successfully configured {name}")
        elif current == "active":
            if not manager.switch([], [name], 5.0).ok:
                raise LaunchError("Error stopping controller, check controller_manager "
                                  "logs")
            print(f"Successfully deactivated {name}")
        else:
            raise LaunchError(f"cannot put {name} in 'inactive' state from its current "
                              f"state {current}")
    else:
        if current != "inactive":
            raise LaunchError(f"cannot activate {name} from its current state {current}")
        response = manager.switch([name], [], 5.0)
        if not response.ok:
            raise LaunchError(f"Error activating {name}, check controller_manager logs"
                              f"{': ' + response.message if response.message else ''}")
        print(f"Successfully activated {name}")
    return 0
