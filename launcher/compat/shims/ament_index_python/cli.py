"""ament_index_python.cli: the `ament_index` command: the resource types, the resources of a
type (with their prefixes), or one resource's content."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ament_index_python.resources import get_resource, get_resource_types, get_resources


def main(argv: list[str] = sys.argv[1:]) -> int | None:  # noqa: B006 (ament's signature)
    parser = argparse.ArgumentParser(description="Query the ament resource index.")
    parser.add_argument("resource_type", nargs="?", help="list the resources of this type")
    parser.add_argument("resource_name", nargs="?", help="print this resource's content")
    args = parser.parse_args(argv)
    if args.resource_type is None:
        for name in sorted(get_resource_types()):
            print(name)
        return None
    if args.resource_name is None:
        for name, prefix in sorted(get_resources(args.resource_type).items()):
            print(f"{name}\t{prefix}")
        return None
    try:
        content, prefix = get_resource(args.resource_type, args.resource_name)
    except LookupError as exc:
        return str(exc)  # type: ignore[return-value]
    print(prefix)
    if content:
        print("<<<")
        print(content)
        print(">>>")
    return None


def resource_type_completer(prefix: str, **kwargs: Any) -> list[str]:
    return sorted(t for t in get_resource_types() if t.startswith(prefix))


def resource_name_completer(prefix: str, parsed_args: Any, **kwargs: Any) -> list[str]:
    kind = getattr(parsed_args, "resource_type", None)
    if not kind:
        return []
    return sorted(n for n in get_resources(kind) if n.startswith(prefix))
