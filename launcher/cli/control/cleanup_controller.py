"""`launcher control cleanup_controller`: clean up a controller."""

from __future__ import annotations

import argparse

from launcher.cli.control.manager import add_manager_option, simple_call


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("controller_name", help="the controller")
    add_manager_option(parser)


run = simple_call("cleanup_controller", "controller_name",
                  "Successfully cleaned up controller {}",
                  "Error cleaning up controller {}, check controller_manager logs")
