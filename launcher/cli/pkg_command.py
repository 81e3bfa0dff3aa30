"""`launcher pkg list | prefix | share | executables | xml | create`."""

from __future__ import annotations

import argparse
import sys

from launcher.cli import completion
from launcher.cli.workspace import load_index
from launcher.packages.executables import executables


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("pkg", help="packages: list, find, create",
                            description="Packages in the workspaces launcher can see.")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="every package, with where it is")
    listing.add_argument("--names", action="store_true",
                         help="the names alone, as `ros2 pkg list` prints them")
    listing.set_defaults(run=run_list)
    for verb, helptext in (("prefix", "the install prefix of a package"),
                           ("share", "the share folder of a package (the package itself)"),
                           ("xml", "the package.xml of a package")):
        sub = verbs.add_parser(verb, help=helptext)
        sub.add_argument("package", metavar="PKG", help="a package").completer = \
            completion.packages  # type: ignore[attr-defined]
        sub.set_defaults(run=run_lookup, verb=verb)
    exe = verbs.add_parser("executables", help="the executables of one or every package")
    exe.add_argument("package", metavar="PKG", nargs="?", help="a package (default: all)")
    exe.set_defaults(run=run_executables)
    create = verbs.add_parser("create", help="write a new package from templates")
    create.add_argument("name", metavar="NAME", help="the new package's name")
    create.add_argument("--dependencies", nargs="*", default=[], metavar="PKG",
                        help="packages it depends on (package.xml <depend>)")
    create.add_argument("--destination-directory", default=".", metavar="DIR",
                        help="where to make it (default: here)")
    create.add_argument("--description", default="A launcher package.",
                        help="its package.xml description")
    create.set_defaults(run=run_create)


def run_list(args: argparse.Namespace) -> int:
    for package in sorted(load_index(), key=lambda p: p.name):
        print(package.name if args.names else
              f"{package.name:30} {package.origin:9} {package.path}")
    return 0


def run_lookup(args: argparse.Namespace) -> int:
    index = load_index()
    if args.verb == "share":
        print(index.share(args.package))
    elif args.verb == "prefix":
        print(index.prefix(args.package))
    else:
        sys.stdout.write(index.get(args.package).manifest.read_text())
    return 0


def run_executables(args: argparse.Namespace) -> int:
    index = load_index()
    packages = [index.get(args.package)] if args.package else sorted(index, key=lambda p: p.name)
    for package in packages:
        for name, found in sorted(executables(package).items()):
            note = "" if found.runnable else "  (not executable: chmod +x it)"
            print(f"{package.name} {name}{note}")
    return 0


def run_create(args: argparse.Namespace) -> int:
    from launcher.packages.scaffold import create_package  # jinja2: only here (start-up time)

    folder = create_package(args.name, args.destination_directory, args.dependencies,
                            args.description)
    print(f"created package '{args.name}' in {folder}")
    return 0
