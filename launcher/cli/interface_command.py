"""`launcher interface list | show | proto | package | packages`, as `ros2 interface` has
them: the distro's message types (the pinned type store) and the packages' own `.msg` and
`.srv` files."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.errors import LaunchError, did_you_mean


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("interface", help="message and service types")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="every message and service type")
    only = listing.add_mutually_exclusive_group()
    only.add_argument("-m", "--only-msgs", action="store_true", help="messages only")
    only.add_argument("-s", "--only-srvs", action="store_true", help="services only")
    listing.set_defaults(run=run_list)
    show = verbs.add_parser("show", help="a type's definition (nested types indented)")
    show.add_argument("type", help="pkg/msg/Name or pkg/srv/Name")
    show.set_defaults(run=run_show)
    proto = verbs.add_parser("proto", help="a message's fields with their defaults, as YAML")
    proto.add_argument("type", help="a message type, e.g. geometry_msgs/msg/Twist")
    proto.set_defaults(run=run_proto)
    package = verbs.add_parser("package", help="the types of one package")
    package.add_argument("package", help="a package")
    package.set_defaults(run=run_package)
    verbs.add_parser("packages", help="the packages that have types").set_defaults(
        run=run_packages)


def all_types() -> dict[str, list[str]]:
    """{'msg': [...], 'srv': [...]}: the distro's and the packages' types."""
    from launcher.bus.types import registry
    from launcher.packages.index import PackageIndex

    messages = {n for n in registry().known() if "/msg/" in n}
    services: set[str] = set()
    for package in PackageIndex.from_environment():
        for kind, found in (("msg", messages), ("srv", services)):
            folder = package.path / kind
            if folder.is_dir():
                found.update(f"{package.name}/{kind}/{p.stem}" for p in folder.glob(f"*.{kind}"))
    return {"msg": sorted(messages), "srv": sorted(services)}


def run_list(args: argparse.Namespace) -> int:
    types = all_types()
    for kind, title in (("msg", "Messages"), ("srv", "Services")):
        if (kind == "msg" and args.only_srvs) or (kind == "srv" and args.only_msgs):
            continue
        print(f"{title}:")
        for name in types[kind]:
            print(f"    {name}")
    return 0


def run_packages(_args: argparse.Namespace) -> int:
    types = all_types()
    for name in sorted({t.split("/")[0] for kind in types.values() for t in kind}):
        print(name)
    return 0


def run_package(args: argparse.Namespace) -> int:
    types = all_types()
    mine = [t for kind in types.values() for t in kind if t.split("/")[0] == args.package]
    if not mine:
        packages = sorted({t.split("/")[0] for kind in types.values() for t in kind})
        raise LaunchError(f"no types in package '{args.package}'"
                          f"{did_you_mean(args.package, packages)}")
    for name in sorted(mine):
        print(name)
    return 0


def run_show(args: argparse.Namespace) -> int:
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
    _known(name)
    print("\n".join(_lines(name, "")))
    return 0


def run_proto(args: argparse.Namespace) -> int:
    import yaml

    from launcher.bus.messages import build, to_data
    from launcher.bus.types import normalize

    name = normalize(args.type)
    _known(name)
    data = to_data(build(name, {}))
    print(f'"{yaml.safe_dump(data, default_flow_style=False, sort_keys=False)}"')
    return 0


def _known(name: str) -> None:
    from launcher.bus.types import registry

    try:
        registry().ensure(name)
    except LaunchError:
        raise LaunchError(f"unknown type '{name}'"
                          f"{did_you_mean(name, [t for k in all_types().values() for t in k])}"
                          ) from None


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


def type_text(kind: int, detail: Any) -> tuple[str, str | None]:
    """('geometry_msgs/Vector3[]', 'geometry_msgs/msg/Vector3') for a field's kind."""
    from launcher.bus import kinds
    from launcher.bus.interfaces import ros1_spelling

    if kind == kinds.BASE:
        base, bound = detail
        return (f"{base}<={bound}" if bound else base), None
    if kind == kinds.NAME:
        return ros1_spelling(detail), detail
    inner, size = detail
    text, nested = type_text(*inner)
    if kind == kinds.ARRAY:
        return f"{text}[{size}]", nested
    return (f"{text}[<={size}]" if size else f"{text}[]"), nested

