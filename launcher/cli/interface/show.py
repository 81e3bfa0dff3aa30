"""`launcher interface show`: a type's definition (nested types indented)."""

from __future__ import annotations

import argparse

from launcher.cli.interface.types import ensure_known, type_text


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("type", help="pkg/msg/Name or pkg/srv/Name")


def run(args: argparse.Namespace) -> int:
    from launcher.bus.types import normalize, registry

    name = normalize(args.type)
    text = _file_text(name)
    if text is not None:  # a package's own file: as written, comments and all
        print(text.rstrip("\n"))
        return 0
    if name.count("/") == 2 and name.split("/")[1] == "srv":
        request, response = registry().service(name)
        print("\n".join([*_lines(request, ""), "---", *_lines(response, "")]))
        return 0
    ensure_known(name)
    print("\n".join(_lines(name, "")))
    return 0


def _file_text(name: str) -> str | None:
    """The `.msg`/`.srv` file a package has for `name`, if one has."""
    from launcher.bus.interfaces import find_definition
    from launcher.packages.index import PackageIndex

    parts = name.split("/")
    if len(parts) != 3:
        return None
    index = PackageIndex.from_environment()
    if parts[0] not in index:
        return None
    found = find_definition(name, index.share(parts[0]))
    return found[1].read_text(encoding="utf-8") if found else None


def _lines(name: str, indent: str) -> list[str]:
    """A type's constants and fields, each nested message's own indented under it (as
    `ros2 interface show` prints them)."""
    from launcher.bus.types import registry

    registry().ensure(name)
    constants, fields = registry().fielddefs[name]
    lines = [f"{indent}{kind} {constant}={value}" for constant, kind, value in constants]
    for field, (kind, detail) in fields:
        text, nested = type_text(kind, detail)
        lines.append(f"{indent}{text} {field}")
        if nested is not None:
            lines += _lines(nested, indent + "\t")
    return lines
