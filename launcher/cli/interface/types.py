"""The interface types launcher knows, and how a field's type is written."""

from __future__ import annotations

from typing import Any

from launcher.errors import LaunchError, did_you_mean


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


def ensure_known(name: str) -> None:
    from launcher.bus.types import registry

    try:
        registry().ensure(name)
    except LaunchError:
        raise LaunchError(f"unknown type '{name}'"
                          f"{did_you_mean(name, [t for k in all_types().values() for t in k])}"
                          ) from None


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
