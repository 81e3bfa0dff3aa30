"""`launcher pkg create`: write a new package from templates."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", metavar="NAME", help="the new package's name")
    parser.add_argument("--dependencies", nargs="*", default=[], metavar="PKG",
                        help="packages it depends on (package.xml <depend>)")
    parser.add_argument("--destination-directory", default=".", metavar="DIR",
                        help="where to make it (default: here)")
    parser.add_argument("--description", default="A launcher package.",
                        help="its package.xml description")


def run(args: argparse.Namespace) -> int:
    from launcher.packages.scaffold import create_package  # jinja2: only here (start-up time)

    folder = create_package(args.name, args.destination_directory, args.dependencies,
                            args.description)
    print(f"created package '{args.name}' in {folder}")
    return 0
