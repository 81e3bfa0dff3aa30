"""`rospack find | list | list-names | depends1`, as ROS 1's rospack: a package's folder is
where launcher finds it (its source folder, used in place)."""

from __future__ import annotations

import argparse

from launcher.arguments import Parser


def parser(prog: str = "rospack") -> Parser:
    p = Parser(prog=prog, description="rospack is a command-line tool for retrieving "
                                      "information about ROS packages.")
    verbs = p.add_subparsers(dest="verb", metavar="COMMAND", required=True)
    find = verbs.add_parser("find", help="print the absolute path to the package")
    find.add_argument("package", help="a package")
    find.set_defaults(run=run_find)
    verbs.add_parser("list", help="print newline-separated list of <package-name> "
                                  "<package-dir> for all packages").set_defaults(run=run_list)
    verbs.add_parser("list-names", help="print newline-separated list of package names for "
                                        "all packages").set_defaults(run=run_list)
    depends = verbs.add_parser("depends1", help="print the package's direct dependencies")
    depends.add_argument("package", help="a package")
    depends.set_defaults(run=run_depends)
    return p


def main(argv: list[str], prog: str = "rospack") -> int:
    args = parser(prog).parse_args_strictly(argv)
    return int(args.run(args) or 0)


def run_find(args: argparse.Namespace) -> int:
    from launcher.cli.workspace import load_index
    from launcher.errors import LaunchError
    from launcher.packages.index import PackageNotFound

    try:
        print(load_index().share(args.package))
    except PackageNotFound as exc:  # rospack's words first, then where it looked
        raise LaunchError(f"[rospack] Error: package '{args.package}' not found; "
                          f"{str(exc).split('; ', 1)[-1]}") from None
    return 0


def run_list(args: argparse.Namespace) -> int:
    from launcher.cli.workspace import load_index

    for package in sorted(load_index(), key=lambda p: p.name):
        print(package.name if args.verb == "list-names" else f"{package.name} {package.path}")
    return 0


def run_depends(args: argparse.Namespace) -> int:
    from launcher.cli.workspace import load_index

    package = load_index().get(args.package)
    tags = ("depend", "build_depend", "exec_depend", "run_depend", "buildtool_depend")
    for name in sorted({n for tag in tags for n in package.dependencies.get(tag, [])}):
        print(name)
    return 0
