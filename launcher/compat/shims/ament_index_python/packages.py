"""ament_index_python.packages, answered from launcher's package index."""

from __future__ import annotations

from pathlib import Path

import launcher.compat
from launcher.packages.index import PackageIndex, PackageNotFound


class PackageNotFoundError(KeyError):
    pass


def _index() -> PackageIndex:
    if launcher.compat.current_index is None:
        launcher.compat.current_index = PackageIndex.from_environment()
    return launcher.compat.current_index


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
