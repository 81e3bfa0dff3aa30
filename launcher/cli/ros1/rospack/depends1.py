"""`rospack depends1`: a package's direct dependencies."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package", help="a package")


def run(args: argparse.Namespace) -> int:
    from launcher.cli.workspace import load_index

    package = load_index().get(args.package)
    tags = ("depend", "build_depend", "exec_depend", "run_depend", "buildtool_depend")
    for name in sorted({n for tag in tags for n in package.dependencies.get(tag, [])}):
        print(name)
    return 0
