"""`rosmsg show | list | package` and `rossrv show | list | package`, as ROS 1 prints them:
fields with nested types expanded two spaces deeper, `time`/`duration` for the builtin
stamps, and a type given without its package (`rosmsg show Twist`) looked up in every
package, each match under a `[pkg/Type]:` heading."""

from __future__ import annotations

import argparse

from launcher.arguments import Parser
from launcher.bus.interfaces import ros1_spelling
from launcher.errors import LaunchError, did_you_mean

BUILTIN = {"builtin_interfaces/msg/Time": "time", "builtin_interfaces/msg/Duration": "duration"}


def parser(prog: str) -> Parser:
    kind = "srv" if prog == "rossrv" else "msg"
    noun = "Service" if kind == "srv" else "Message"
    p = Parser(prog=prog, description=f"{prog} is a command-line tool for displaying "
                                      f"information about ROS {noun} types.")
    verbs = p.add_subparsers(dest="verb", metavar="COMMAND", required=True)
    show = verbs.add_parser("show", help=f"show {kind} description")
    show.add_argument("type", help="pkg/Type, or Type alone (every package's)")
    show.set_defaults(run=run_show)
    verbs.add_parser("list", help=f"list all {kind}s").set_defaults(run=run_list)
    package = verbs.add_parser("package", help=f"list {kind}s in a package")
    package.add_argument("package", help="a package")
    package.set_defaults(run=run_package)
    p.set_defaults(kind=kind)
    return p


def main(argv: list[str], prog: str = "rosmsg") -> int:
    args = parser(prog).parse_args_strictly(argv)
    return int(args.run(args) or 0)


def _types(kind: str) -> list[str]:
    from launcher.cli.interface_command import all_types

    return all_types()[kind]


def run_list(args: argparse.Namespace) -> int:
    for name in sorted({ros1_spelling(t) for t in _types(args.kind)}):
        print(name)
    return 0


def run_package(args: argparse.Namespace) -> int:
    found = sorted({ros1_spelling(t) for t in _types(args.kind)
                    if t.split("/")[0] == args.package})
    if not found:
        raise LaunchError(f"Unknown package [{args.package}] or it has no {args.kind}s")
    for name in found:
        print(name)
    return 0


def run_show(args: argparse.Namespace) -> int:
    known = _types(args.kind)
    wanted = args.type
    if "/" in wanted:
        package, base = wanted.split("/")[0], wanted.split("/")[-1]
        matches = [f"{package}/{args.kind}/{base}"]
        if matches[0] not in known:
            raise LaunchError(f"Unable to load msg [{wanted}]"
                              f"{did_you_mean(wanted, [ros1_spelling(t) for t in known])}")
    else:
        matches = sorted(t for t in known if t.split("/")[-1] == wanted)
        if not matches:
            raise LaunchError(f"Could not find {args.kind} '{wanted}'"
                              f"{did_you_mean(wanted, {t.split('/')[-1] for t in known})}")
    for number, name in enumerate(matches):
        if len(matches) > 1 or "/" not in wanted:
            print(f"[{ros1_spelling(name)}]:")
        print("\n".join(definition(name)))
        if number < len(matches) - 1:
            print()
    return 0


def definition(name: str) -> list[str]:
    from launcher.bus.types import registry

    if "/srv/" in name:
        request, response = registry().service(name)
        return [*_lines(request, ""), "---", *_lines(response, "")]
    return _lines(name, "")


def _lines(name: str, indent: str) -> list[str]:
    from launcher.bus.types import registry
    from launcher.cli.interface_command import type_text

    registry().ensure(name)
    constants, fields = registry().fielddefs[name]
    lines = [f"{indent}{kind} {constant}={value}" for constant, kind, value in constants]
    for field, (kind, detail) in fields:
        text, nested = type_text(kind, detail)
        if nested in BUILTIN:
            text, nested = text.replace(ros1_spelling(nested), BUILTIN[nested]), None
        lines.append(f"{indent}{text} {field}")
        if nested is not None:
            lines += _lines(nested, indent + "  ")
    return lines
