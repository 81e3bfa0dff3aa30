"""`launcher pkg xml`: the package.xml of a package."""

from __future__ import annotations

import argparse

from launcher.cli import completion
from launcher.cli.pkg.lookup import lookup


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package", metavar="PKG", help="a package").completer = \
        completion.packages  # type: ignore[attr-defined]


def run(args: argparse.Namespace) -> int:
    return lookup(args, "xml")
