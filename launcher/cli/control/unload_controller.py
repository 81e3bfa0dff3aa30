"""`launcher control unload_controller`: unload a controller."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_manager_option, simple_call


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("controller_name", help="the controller")
    add_manager_option(parser)


run = simple_call("unload_controller", "controller_name", "Successfully unloaded controller {}",
                  "Error unloading controller {}, check controller_manager logs")
