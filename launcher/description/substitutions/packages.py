"""Packages: `$(find-pkg-share PKG)` (roslaunch's `$(find PKG)` too), `$(find-pkg-prefix
PKG)`, `$(exec-in-pkg EXE PKG)`, and `$(param NAME [default])` (a parameter set with
set_parameter)."""

from __future__ import annotations

import shlex
from collections.abc import Mapping
from typing import ClassVar

from launcher.description.parameters import global_parameters
from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.description.substitutions.lookup import Lookup
from launcher.errors import LaunchError
from launcher.packages.executables import find_executable
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


def _index(sub: Substitution, context: LaunchContext):
    if context.packages is None:
        raise sub.fail(f"$({sub.names[0]}) needs the package index, which this run lacks")
    return context.packages


@dataclass(frozen=True)
class _PackageFolder(Substitution):
    """A folder of the package: the index's `share` or `prefix` of it."""

    package: Text_
    _folder: ClassVar[str]

    def perform(self, context: LaunchContext) -> str:
        find = getattr(_index(self, context), self._folder)
        try:
            return str(find(perform_text(context, self.package)))
        except LaunchError as exc:
            raise exc.at(self.where) from None


@substitution("find-pkg-share")
@dataclass(frozen=True)
class FindPackageShare(_PackageFolder):
    """The package's folder (packages are used in place)."""

    _folder = "share"


@substitution("find-pkg-prefix")
@dataclass(frozen=True)
class FindPackagePrefix(_PackageFolder):
    """A prefix whose share/<package> is the package."""

    _folder = "prefix"


@substitution("exec-in-pkg")
@dataclass(frozen=True)
class ExecutableInPackage(Substitution):
    """The command that runs EXE of PKG (a path, or an interpreter line for entry points)."""

    executable: Text_
    package: Text_

    def perform(self, context: LaunchContext) -> str:
        try:
            package = _index(self, context).get(perform_text(context, self.package))
            found = find_executable(package, perform_text(context, self.executable))
        except LaunchError as exc:
            raise exc.at(self.where) from None
        return str(found.path) if found.path is not None else shlex.join(found.argv)


@substitution("param")
@dataclass(frozen=True)
class Parameter(Lookup):
    """A global parameter set earlier with set_parameter."""

    def _values(self, context: LaunchContext) -> Mapping[str, str]:
        return {name: str(value).lower() if isinstance(value, bool) else str(value)
                for name, value in global_parameters(context).items()}

    def _unset(self, name: str, values: Mapping[str, str]) -> str:
        return (f"parameter '{name}' is not set; set it with set_parameter or give a "
                f"default: $(param {name} DEFAULT)")
