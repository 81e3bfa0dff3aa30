"""Packages: `$(find-pkg-share PKG)` (roslaunch's `$(find PKG)` too), `$(find-pkg-prefix
PKG)`, `$(exec-in-pkg EXE PKG)`, and `$(param NAME [default])` (a parameter set with
set_parameter)."""

from __future__ import annotations

import shlex

from launcher.description.parameters import global_parameters
from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.errors import LaunchError
from launcher.packages.executables import find_executable
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


def _index(sub: Substitution, context: LaunchContext):
    if context.packages is None:
        raise sub.fail(f"$({sub.names[0]}) needs the package index, which this run lacks")
    return context.packages


def _lookup(sub: Substitution, context: LaunchContext, what: str, package: Text_) -> str:
    """`share` or `prefix` of the package, with errors placed at the substitution."""
    try:
        return str(getattr(_index(sub, context), what)(perform_text(context, package)))
    except LaunchError as exc:
        raise exc.at(sub.where) from None


@substitution("find-pkg-share")
@dataclass(frozen=True)
class FindPackageShare(Substitution):
    """The package's folder (packages are used in place)."""

    package: Text_

    def perform(self, context: LaunchContext) -> str:
        return _lookup(self, context, "share", self.package)


@substitution("find-pkg-prefix")
@dataclass(frozen=True)
class FindPackagePrefix(Substitution):
    """A prefix whose share/<package> is the package."""

    package: Text_

    def perform(self, context: LaunchContext) -> str:
        return _lookup(self, context, "prefix", self.package)


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
class Parameter(Substitution):
    """A global parameter set earlier with set_parameter."""

    name: Text_
    default: Text_ | None = None

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        parameters = dict(global_parameters(context))
        if name in parameters:
            value = parameters[name]
            return str(value).lower() if isinstance(value, bool) else str(value)
        if self.default is not None:
            return perform_text(context, self.default)
        raise self.fail(f"parameter '{name}' is not set; set it with set_parameter or give a "
                        f"default: $(param {name} DEFAULT)")
