"""ament_index_python.packages, answered from launcher's package index."""

from __future__ import annotations

import os
from pathlib import Path

from ament_index_python.resources import get_resource, get_resources, get_search_paths  # noqa: F401
from launcher.packages.index import PackageIndex, PackageNotFound


class PackageNotFoundError(KeyError):
    pass


_built: dict[tuple[str, ...], PackageIndex] = {}


def _index() -> PackageIndex:
    """The index for the environment as it is now (a Python launch file's look-ups are many:
    one index per set of search paths, rebuilt when they change)."""
    key = (os.environ.get("LAUNCHER_PACKAGE_PATH", ""), os.environ.get("AMENT_PREFIX_PATH", ""),
           os.getcwd())
    if key not in _built:
        _built[key] = PackageIndex.from_environment()
    return _built[key]


def get_package_share_directory(package_name: str, print_warning: bool = True) -> str:
    try:
        return str(_index().share(package_name))
    except PackageNotFound as exc:
        raise PackageNotFoundError(exc.message) from None


def get_package_share_path(package_name: str, print_warning: bool = True) -> Path:
    return Path(get_package_share_directory(package_name))


def get_package_prefix(package_name: str) -> str:
    try:
        return str(_index().prefix(package_name))
    except PackageNotFound as exc:
        raise PackageNotFoundError(exc.message) from None


def get_packages_with_prefixes() -> dict[str, str]:
    index = _index()
    return {package.name: str(index.prefix(package.name)) for package in index}
