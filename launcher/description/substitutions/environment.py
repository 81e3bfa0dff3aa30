"""Environment variables: `$(env NAME [default])` (roslaunch's `$(env)` and `$(optenv)`
too)."""

from __future__ import annotations

from collections.abc import Mapping

from launcher.description.substitution import substitution
from launcher.description.substitutions.lookup import Lookup
from launcher.errors import did_you_mean
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@substitution("env")
@dataclass(frozen=True)
class EnvironmentVariable(Lookup):
    """The variable from the launch's environment (including `set_env` changes)."""

    def _values(self, context: LaunchContext) -> Mapping[str, str]:
        return context.environment

    def _unset(self, name: str, values: Mapping[str, str]) -> str:
        return (f"environment variable '{name}' is not set{did_you_mean(name, values)}"
                f"; give a default with {self.spelling(name)}")

    def spelling(self, name: str) -> str:
        return f"$(env {name} DEFAULT)"


@substitution("roslaunch_env")
@dataclass(frozen=True)
class RoslaunchEnvironmentVariable(EnvironmentVariable):
    """roslaunch's `$(env)` and `$(optenv)`: roslaunch's own environment, as the launch began
    (its `<env>` tags set the nodes' environment, not roslaunch's)."""

    def _values(self, context: LaunchContext) -> Mapping[str, str]:
        return context.initial_environment

    def spelling(self, name: str) -> str:
        return f"$(optenv {name} DEFAULT)"
