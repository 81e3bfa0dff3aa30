"""The environment of the processes a launch starts: set, unset, append, reset."""

from __future__ import annotations

import os
from typing import Any

from launcher.description.action import Action
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import Text_, perform_text
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@action("set_env")
@dataclass(kw_only=True, eq=False)
class SetEnvironmentVariable(Action):
    name: Text_ = attr(Kind.TEXT, required=True, doc="Variable name.")
    value: Text_ = attr(Kind.TEXT, required=True, doc="New value.")

    def execute(self, context: LaunchContext) -> None:
        context.environment[perform_text(context, self.name)] = perform_text(context,
                                                                            self.value)


@action("unset_env")
@dataclass(kw_only=True, eq=False)
class UnsetEnvironmentVariable(Action):
    name: Text_ = attr(Kind.TEXT, required=True, doc="Variable name.")

    def execute(self, context: LaunchContext) -> None:
        context.environment.pop(perform_text(context, self.name), None)


@action("append_env")
@dataclass(kw_only=True, eq=False)
class AppendEnvironmentVariable(Action):
    name: Text_ = attr(Kind.TEXT, required=True, doc="Variable name.")
    value: Text_ = attr(Kind.TEXT, required=True, doc="Value to add.")
    prepend: Any = attr(Kind.BOOL, False, doc="Put it in front instead of at the end.")
    separator: Any = attr(Kind.TEXT, os.pathsep, doc="Between the old and the new value.")

    def execute(self, context: LaunchContext) -> None:
        name = perform_text(context, self.name)
        value = perform_text(context, self.value)
        old = context.environment.get(name, "")
        sep = resolve(context, self.separator, Kind.TEXT, "separator")
        if not old:
            context.environment[name] = value
        elif resolve(context, self.prepend, Kind.BOOL, "prepend"):
            context.environment[name] = value + sep + old
        else:
            context.environment[name] = old + sep + value


@action("reset_env")
@dataclass(kw_only=True, eq=False)
class ResetEnvironment(Action):
    """Back to the environment the launch started with."""

    def execute(self, context: LaunchContext) -> None:
        context.environment.clear()
        context.environment.update(context.initial_environment)
