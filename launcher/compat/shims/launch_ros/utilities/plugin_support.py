"""launch_ros.utilities.plugin_support: version checks of Node action extensions."""

from __future__ import annotations


class PluginException(Exception):
    """An extension that cannot be used."""


def _numbers(version: str) -> tuple[int, ...]:
    return tuple(int(part) for part in version.split(".") if part.isdigit())


def get_upper_bound_caret_version(version: str) -> str:
    """The first version a caret range (`^1.2.3`) excludes: the next major (next minor or
    patch while those before are 0)."""
    parts = list(_numbers(version)) + [0] * (3 - len(_numbers(version)))
    for index, part in enumerate(parts):
        if part != 0 or index == len(parts) - 1:
            upper = parts[:index] + [part + 1] + [0] * (len(parts) - index - 1)
            return ".".join(str(p) for p in upper)
    return version


def satisfies_version(version: str, caret_range: str) -> None:
    """Raise PluginException unless `version` is in `caret_range` (`^1.2.3`)."""
    lower = caret_range.lstrip("^")
    upper = get_upper_bound_caret_version(lower)
    if not _numbers(lower) <= _numbers(version) < _numbers(upper):
        raise PluginException(f"version {version} is not in {caret_range} "
                              f"(from {lower}, before {upper})")


__all__ = ["PluginException", "get_upper_bound_caret_version", "satisfies_version"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
