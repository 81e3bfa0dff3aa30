"""What the hardware verbs (list_hardware_components, list_hardware_interfaces) share: their
options, and an interface's words as ros2controlcli prints them."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.cli.control.manager import add_manager_option


def add_hardware_arguments(parser: argparse.ArgumentParser, verbose: str) -> None:
    """`-v/--verbose` (what it adds: `verbose`) and `-c/--controller-manager`."""
    parser.add_argument("-v", "--verbose", action="store_true", help=verbose)
    add_manager_option(parser)


def availability(interface: Any) -> str:
    return "[available]" if interface.is_available else "[unavailable]"


def command_interface(interface: Any, verbose: bool) -> str:
    """`name [data type] [available] [claimed]`, the data type with -v only."""
    kind = f" [{interface.data_type}]" if verbose else ""
    claim = "[claimed]" if interface.is_claimed else "[unclaimed]"
    return f"{interface.name}{kind} {availability(interface)} {claim}"
