"""`rospack find`: the absolute path to a package."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package", help="a package")


def run(args: argparse.Namespace) -> int:
    from launcher.cli.workspace import load_index
    from launcher.errors import LaunchError
    from launcher.packages.index import PackageNotFound

    try:
        print(load_index().share(args.package))
    except PackageNotFound as exc:  # rospack's words first, then where it looked
        raise LaunchError(f"[rospack] Error: package '{args.package}' not found; "
                          f"{str(exc).split('; ', 1)[-1]}") from None
    return 0
