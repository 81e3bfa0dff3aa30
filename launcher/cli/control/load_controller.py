"""`launcher control load_controller`: load a controller."""

from __future__ import annotations

import argparse
import os
import sys

from launcher.cli.control.manager import add_manager_option, on_manager, state_of
from launcher.nodes.spawner import Manager, type_from


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("controller_name", help="the controller (a name in the manager's YAML)")
    parser.add_argument("param_file", nargs="?", help="a YAML file with its parameters")
    parser.add_argument("--set-state", choices=("inactive", "active"),
                        help="configure it (inactive), or configure and activate it (active)")
    add_manager_option(parser)


@on_manager
def run(manager: Manager, args: argparse.Namespace) -> int:
    name = args.controller_name
    if state_of(manager, name):
        print(f"Controller : {name} already loaded, skipping load_controller!")
    else:
        if args.param_file:
            path = os.path.abspath(args.param_file)
            if not os.path.exists(path):
                print(f"Controller parameter file : {args.param_file} does not exist, "
                      f"Aborting!", file=sys.stderr)
                return 1
            type_name, found = type_from([path], name, "/")
            if found:
                manager.set_parameter(f"{name}.params_file", str([path]))
                if type_name:
                    manager.set_parameter(f"{name}.type", type_name)
        if not manager.call("load_controller", name=name).ok:
            print(f"Failed loading controller {name} check controller_manager logs",
                  file=sys.stderr)
            return 1
        print(f"Successfully loaded controller {name}")
    if args.set_state:
        if not manager.call("configure_controller", name=name).ok:
            print(f"Error configuring controller : {name}", file=sys.stderr)
            return 1
        if args.set_state == "active" and not manager.switch([name], [], 5.0).ok:
            print(f"Error activating controller : {name}, check controller_manager logs",
                  file=sys.stderr)
            return 1
        print(f"Successfully loaded controller {name} into state {args.set_state}")
    return 0
