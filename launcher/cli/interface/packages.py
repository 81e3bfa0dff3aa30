"""`launcher interface packages`: the packages that have types."""

from __future__ import annotations

import argparse

from launcher.cli.interface.types import all_types


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pass


def run(_args: argparse.Namespace) -> int:
    types = all_types()
    for name in sorted({t.split("/")[0] for kind in types.values() for t in kind}):
        print(name)
    return 0
