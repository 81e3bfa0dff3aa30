"""`launcher pkg executables`: the executables of one or every package."""

from __future__ import annotations

import argparse

from launcher.cli.workspace import load_index
from launcher.packages.executables import executables


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package", metavar="PKG", nargs="?", help="a package (default: all)")


def run(args: argparse.Namespace) -> int:
    index = load_index()
    packages = [index.get(args.package)] if args.package else sorted(index, key=lambda p: p.name)
    for package in packages:
        for name, found in sorted(executables(package).items()):
            note = "" if found.runnable else "  (not executable: chmod +x it)"
            print(f"{package.name} {name}{note}")
    return 0
