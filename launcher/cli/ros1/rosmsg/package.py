"""`rosmsg package` / `rossrv package`: the types of one package."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.cli.ros1.rosmsg.types import types_of
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package", help="a package")


def run(args: argparse.Namespace) -> int:
    found = sorted({ros1_spelling(t) for t in types_of(args.kind)
                    if t.split("/")[0] == args.package})
    if not found:
        raise LaunchError(f"Unknown package [{args.package}] or it has no {args.kind}s")
    for name in found:
        print(name)
    return 0
