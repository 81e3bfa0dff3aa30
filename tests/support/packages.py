"""Packages, package.xml files and package indexes made for a test."""

from __future__ import annotations

import os
import textwrap
from pathlib import Path

from launcher.packages.index import PackageIndex


def manifest(name: str, depends: tuple[str, ...] = (), extra: str = "") -> str:
    deps = "".join(f"<depend>{d}</depend>" for d in depends)
    return (f'<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n'
            f"  <version>1.2.3</version>\n  <description>d</description>\n"
            f'  <maintainer email="m@x">m</maintainer>\n  <license>MIT</license>\n'
            f"  {deps}{extra}\n</package>\n")


def make_tree(root: Path, files: dict[str, str], executable: tuple[str, ...] = ()) -> Path:
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text))
        if relative in executable:
            path.chmod(0o755)
    return root


def index_for(*roots: Path, ament: str = "", tmp: Path | None = None) -> PackageIndex:
    env = {"LAUNCHER_PACKAGE_PATH": os.pathsep.join(map(str, roots)),
           "AMENT_PREFIX_PATH": ament, "LAUNCHER_CACHE_DIR": str((tmp or roots[0]) / ".cache")}
    return PackageIndex.from_environment(env, cwd=Path("/"))
