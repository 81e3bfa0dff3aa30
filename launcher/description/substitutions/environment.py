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
        if name in context.environment:
            return context.environment[name]
        if self.default is not None:
            return perform_text(context, self.default)
        raise self.fail(
            f"environment variable '{name}' is not set{did_you_mean(name, context.environment)}"
            f"; give a default with $(env {name} DEFAULT)"
        )
