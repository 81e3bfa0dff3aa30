"""`rospack list` and `rospack list-names`: every package (with its folder)."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """(no arguments)"""


def run(args: argparse.Namespace) -> int:
    from launcher.cli.workspace import load_index

    for package in sorted(load_index(), key=lambda p: p.name):
        print(package.name if args.verb == "list-names" else f"{package.name} {package.path}")
    return 0
