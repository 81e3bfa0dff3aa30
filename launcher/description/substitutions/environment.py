"""Environment variables: `$(env NAME [default])` (roslaunch's `$(env)` and `$(optenv)`
too)."""

from __future__ import annotations

from launcher.description.substitution import Substitution, Text_, perform_text, substitution
from launcher.errors import did_you_mean
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@substitution("env")
@dataclass(frozen=True)
class EnvironmentVariable(Substitution):
    """The variable from the launch's environment (including `set_env` changes)."""

    name: Text_
    default: Text_ | None = None

    def perform(self, context: LaunchContext) -> str:
        name = perform_text(context, self.name)
        environment = self.environment(context)
        if name in environment:
            return environment[name]
        if self.default is not None:
            return perform_text(context, self.default)
        raise self.fail(
            f"environment variable '{name}' is not set{did_you_mean(name, environment)}"
            f"; give a default with {self.spelling(name)}"
        )

    def environment(self, context: LaunchContext) -> dict[str, str]:
        return context.environment

    def spelling(self, name: str) -> str:
        return f"$(env {name} DEFAULT)"


@substitution("roslaunch_env")
@dataclass(frozen=True)
class RoslaunchEnvironmentVariable(EnvironmentVariable):
    """roslaunch's `$(env)` and `$(optenv)`: roslaunch's own environment, as the launch began
    (its `<env>` tags set the nodes' environment, not roslaunch's)."""

    def environment(self, context: LaunchContext) -> dict[str, str]:
        return context.initial_environment

    def spelling(self, name: str) -> str:
        return f"$(optenv {name} DEFAULT)"
