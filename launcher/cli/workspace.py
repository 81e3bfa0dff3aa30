"""What every command that uses packages needs: the index and the hooked environment."""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping
from pathlib import Path

from launcher.errors import UsageError, did_you_mean
from launcher.packages.hooks import apply_hooks
from launcher.packages.index import PackageIndex


def load_index(environ: Mapping[str, str] | None = None) -> PackageIndex:
    index = PackageIndex.from_environment(os.environ if environ is None else environ)
    for warning in index.warnings:
        print(f"[WARN] [launch]: {warning}", file=sys.stderr)
    for notice in index.notices:
        print(f"[INFO] [launch]: {notice}", file=sys.stderr)
    return index


def hooked_environment(index: PackageIndex, environ: Mapping[str, str]) -> dict[str, str]:
    return apply_hooks(index, environ)


def find_launch_file(index: PackageIndex, package_name: str, file_name: str) -> Path:
    """FILE in the package's launch/ folder, or anywhere in the package."""
    package = index.get(package_name)
    direct = package.path / "launch" / file_name
    if direct.is_file():
        return direct
    matches = sorted(p for p in package.path.rglob(file_name) if p.is_file())
    if matches:
        return matches[0]
    launch_files = sorted(p.name for p in package.path.rglob("*.launch.*"))
    raise UsageError(f"package '{package_name}' has no launch file '{file_name}'"
                     f"{did_you_mean(file_name, launch_files)}; it has: "
                     f"{', '.join(launch_files) or 'none'}")
