"""ament_index_python's resource index: `<prefix>/share/ament_index/resource_index/<type>/<name>`
in each prefix of AMENT_PREFIX_PATH, the first prefix that has it winning (as in ROS 2). With
no AMENT_PREFIX_PATH there is no resource (ROS 2 raises: under launcher a workspace may have
no install prefix at all)."""

from __future__ import annotations

import os

from ament_index_python.constants import AMENT_PREFIX_PATH_ENV_VAR, RESOURCE_INDEX_SUBFOLDER

RESOURCE_INDEX = RESOURCE_INDEX_SUBFOLDER


class InvalidResourceTypeNameError(ValueError):
    """A resource type that is empty or holds a path separator."""


class InvalidResourceNameError(ValueError):
    """A resource name that is empty or holds a path separator."""


def get_search_paths() -> list[str]:
    """The prefixes of AMENT_PREFIX_PATH that exist, in order."""
    paths = os.environ.get(AMENT_PREFIX_PATH_ENV_VAR, "").split(os.pathsep)
    return [p for p in paths if p and os.path.isdir(p)]


def _check(name: str, what: str) -> None:
    error = InvalidResourceTypeNameError if what == "resource type" else InvalidResourceNameError
    if not name:
        raise error(f"The {what} must not be empty")
    if "/" in name or "\\" in name:
        raise error(f"The {what} must not contain path separators")


def get_resource_types() -> set[str]:
    """The resource types that any prefix has."""
    types: set[str] = set()
    for prefix in get_search_paths():
        folder = os.path.join(prefix, RESOURCE_INDEX)
        if os.path.isdir(folder):
            types.update(name for name in os.listdir(folder)
                         if os.path.isdir(os.path.join(folder, name)))
    return types


def get_resources(resource_type: str) -> dict[str, str]:
    """Every resource of `resource_type`: its name and the prefix it is in."""
    _check(resource_type, "resource type")
    found: dict[str, str] = {}
    for prefix in get_search_paths():
        folder = os.path.join(prefix, RESOURCE_INDEX, resource_type)
        if os.path.isdir(folder):
            for name in sorted(os.listdir(folder)):
                if not name.startswith(".") and os.path.isfile(os.path.join(folder, name)):
                    found.setdefault(name, prefix)
    return found


def has_resource(resource_type: str, resource_name: str) -> str | None:
    """The prefix holding the resource, or None."""
    _check(resource_type, "resource type")
    _check(resource_name, "resource name")
    for prefix in get_search_paths():
        if os.path.isfile(os.path.join(prefix, RESOURCE_INDEX, resource_type, resource_name)):
            return prefix
    return None


def get_resource(resource_type: str, resource_name: str) -> tuple[str, str]:
    """(its content, its prefix); LookupError when no prefix has it."""
    prefix = has_resource(resource_type, resource_name)
    if prefix is None:
        raise LookupError(f"Could not find the resource '{resource_name}' of type "
                          f"'{resource_type}'")
    path = os.path.join(prefix, RESOURCE_INDEX, resource_type, resource_name)
    with open(path, encoding="utf-8") as f:
        return f.read(), prefix


__all__ = ["InvalidResourceNameError", "InvalidResourceTypeNameError",
           "RESOURCE_INDEX_SUBFOLDER", "get_resource", "get_resource_types", "get_resources",
           "get_search_paths", "has_resource"]
