"""`rosmsg show` / `rossrv show`: a type's definition as ROS 1 prints it."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.cli.ros1.rosmsg.types import types_of
from launcher.errors import LaunchError, did_you_mean

BUILTIN = {"builtin_interfaces/msg/Time": "time", "builtin_interfaces/msg/Duration": "duration"}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("type", help="pkg/Type, or Type alone (every package's)")


def run(args: argparse.Namespace) -> int:
    known = types_of(args.kind)
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
    from launcher.cli.interface.types import type_text

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
