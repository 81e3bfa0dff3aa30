"""`include`: read another launch file (any format) and run it here.

As in ROS 2, the arguments given to an include (and its `let`s) stay set for the actions after
it; `scoped: true` keeps them inside (ROS 2's scoped include). A relative `file` is looked up
next to the including file first, then in the working directory.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from launcher.description.action import Action, LaunchDescription, PopScope, PushScope
from launcher.description.actions.arguments import (
    PASS_ALL_ARGS,
    SetLaunchConfiguration,
    check_required,
    declared_args,
)
from launcher.description.actions.entries import NameValue
from launcher.description.fields import Kind, attr, resolve
from launcher.description.parameters import GLOBAL_PARAMETERS
from launcher.description.registry import action
from launcher.description.substitution import perform_text, to_text
from launcher.errors import ExecutionError, LaunchError
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@dataclass(eq=False)
class IncludeArg(NameValue):
    """An argument of the included file, and its value."""


@action("include")
@dataclass(kw_only=True, eq=False)
class IncludeLaunchDescription(Action):
    file: Any = attr(Kind.TEXT, required=True, doc="The launch file to include.")
    launch_arguments: list[Any] = attr(Kind.ENTRIES, name="arg", entry=IncludeArg,
                                       doc="Arguments for the included file.")
    scoped: Any = attr(Kind.BOOL, False, doc="Keep its arguments and lets inside it.")
    pass_all_args: Any = attr(Kind.BOOL, doc="roslaunch's: false (its default) gives the file "
                                             "only the arguments passed to it")
    is_include = True

    def __init__(self, launch_description_source: Any = None, *, file: Any = None,
                 launch_arguments: Any = (), scoped: Any = False, pass_all_args: Any = None,
                 **kwargs: Any) -> None:
        source = file if file is not None else launch_description_source
        given = getattr(source, "launch_description", None)  # a source holding one
        if isinstance(given, LaunchDescription):
            source = given
        self.launch_description_source = launch_description_source
        self.file = source if isinstance(source, LaunchDescription) else \
            to_text(getattr(source, "location", source))
        pairs = launch_arguments.items() if isinstance(launch_arguments, dict) \
            else launch_arguments
        self.launch_arguments = [a if isinstance(a, IncludeArg) else
                                 IncludeArg(to_text(a[0]), to_text(a[1])) for a in pairs]
        self.scoped = scoped
        self.pass_all_args = pass_all_args
        self.condition = kwargs.get("condition")
        self.where = kwargs.get("where")

    def resolve_path(self, context: LaunchContext) -> Path:
        raw = Path(perform_text(context, self.file))
        here = context.files.current
        if not raw.is_absolute() and here is not None and (here.parent / raw).exists():
            raw = here.parent / raw
        path = raw.absolute()
        if not path.exists():
            raise ExecutionError(f"included file '{raw}' does not exist")
        if not path.is_file():
            raise ExecutionError(f"included path '{raw}' is not a file")
        return path

    def load(self, context: LaunchContext) -> LaunchDescription:
        if isinstance(self.file, LaunchDescription):
            return self.file
        path = self.resolve_path(context)
        chain = [p for p in context.files.all if p is not None]
        if path in chain:
            cycle = " -> ".join(str(p) for p in chain[chain.index(path):] + [path])
            raise ExecutionError(f"include cycle: {cycle}")
        if context.load_description is None:
            raise ExecutionError("this context cannot load launch files")
        try:
            return context.load_description(path)
        except LaunchError as exc:
            if exc.location is None:
                raise exc.at(self.where) from None
            raise

    def execute(self, context: LaunchContext) -> Sequence[Action]:
        description = self.load(context)
        values = {perform_text(context, a.name): perform_text(context, a.value)
                  for a in self.launch_arguments}
        check_required(description.actions, {**context.configurations, **values})
        sets: list[Action] = [SetLaunchConfiguration(name=to_text(k), value=to_text(v))
                              for k, v in values.items()]
        if self.pass_all_args is not None:  # roslaunch's include
            every = resolve(context, self.pass_all_args, Kind.BOOL, "pass_all_args")
            mark = SetLaunchConfiguration(name=to_text(PASS_ALL_ARGS),
                                          value=to_text("true" if every else "false"))
            if every:
                return [PushScope(), mark, *sets, description, PopScope()]
            unused = sorted(set(values) - declared_args(description.actions))
            if unused:
                raise ExecutionError(f"unused args [{', '.join(unused)}] for include of "
                                     f"[{self.resolve_path(context)}]: the file declares no such "
                                     "<arg>", self.where)
            # the file sees only what is passed (the launch's ROS settings stay)
            kept = {k: v for k, v in context.configurations.items() if k.startswith("<")}
            # its parameters are the parameter server's: the nodes after the include get them
            return [PushScope(forwarding=False, keep=kept), mark, *sets, description,
                    PopScope(carry=(GLOBAL_PARAMETERS,))]
        if resolve(context, self.scoped, Kind.BOOL, "scoped"):
            return [PushScope(), *sets, description, PopScope()]
        return [*sets, description]
