"""`launcher interface package`: the types of one package."""

from __future__ import annotations

import argparse

from launcher.cli.interface.types import all_types
from launcher.errors import LaunchError, did_you_mean


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package", help="a package")


def run(args: argparse.Namespace) -> int:
    types = all_types()
    mine = [t for kind in types.values() for t in kind if t.split("/")[0] == args.package]
    if not mine:
        packages = sorted({t.split("/")[0] for kind in types.values() for t in kind})
        raise LaunchError(f"no types in package '{args.package}'"
                          f"{did_you_mean(args.package, packages)}")
    for name in sorted(mine):
        print(name)
    return 0
