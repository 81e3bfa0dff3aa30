"""`rosmsg list` / `rossrv list`: every type, in ROS 1's spelling."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.cli.ros1.rosmsg.types import types_of


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """(no arguments)"""


def run(args: argparse.Namespace) -> int:
    for name in sorted({ros1_spelling(t) for t in types_of(args.kind)}):
        print(name)
    return 0
