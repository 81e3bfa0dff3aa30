"""`.in` hook templates, configured like CMake's `configure_file(… @ONLY)`: `@VAR@` replaced.

An unknown `@VAR@` is an error naming the file, line and column (CMake would silently make it
empty).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from pathlib import Path

from launcher.errors import Location, ParseError, did_you_mean
from launcher.packages.manifest import Package

_VARIABLE = re.compile(r"@([A-Za-z_][A-Za-z0-9_]*)@")


def template_variables(package: Package, prefix: Path) -> dict[str, str]:
    return {
        "PROJECT_NAME": package.name, "PACKAGE_NAME": package.name,
        "PROJECT_VERSION": package.version, "PACKAGE_VERSION": package.version,
        "CMAKE_INSTALL_PREFIX": str(prefix), "CMAKE_INSTALL_DATADIR": "share",
        "CMAKE_INSTALL_LIBDIR": "lib", "CMAKE_INSTALL_BINDIR": "bin",
        "CMAKE_CURRENT_SOURCE_DIR": str(package.path), "PROJECT_SOURCE_DIR": str(package.path),
    }


def configure(text: str, variables: Mapping[str, str], file: Path) -> str:
    def replace(match: re.Match[str], line: int, start: int) -> str:
        name = match.group(1)
        if name not in variables:
            where = Location(str(file), line, match.start() - start + 1)
            raise ParseError(f"unknown template variable @{name}@{did_you_mean(name, variables)}"
                             f"; known: {', '.join(sorted(variables))}", where)
        return variables[name]

    lines = text.split("\n")
    return "\n".join(_VARIABLE.sub(lambda m, n=n: replace(m, n, 0), line)
                     for n, line in enumerate(lines, 1))
