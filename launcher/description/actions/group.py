"""`group`: children in a scope of their own (configurations and environment), on a machine
of their own if it names one."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launcher.description.action import Action, PopScope, PushScope
from launcher.description.actions.arguments import KeepEntry, kept_configurations
from launcher.description.actions.machine import PushMachine, machine_attr
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import to_text
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@action("group")
@dataclass(kw_only=True, eq=False)
class GroupAction(Action):
    actions: list[Action] = attr(Kind.CHILDREN, doc="The actions in the group.")
    scoped: Any = attr(Kind.BOOL, True, doc="Changes inside stay inside.")
    forwarding: Any = attr(Kind.BOOL, True,
                           doc="The group sees the configurations set outside it.")
    keep: list[Any] = attr(Kind.ENTRIES, entry=KeepEntry,
                           doc="With forwarding false: configurations still passed in.")
    machine: Any = machine_attr("The machine its processes run on, one a <machine> declares "
                                "(launcher's extension; a process's own machine= wins).")

    def __post_init__(self) -> None:
        super().__post_init__()
        if isinstance(self.keep, dict):  # Python API: launch_configurations={...}
            self.keep = [KeepEntry(to_text(k), to_text(v)) for k, v in self.keep.items()]

    def execute(self, context: LaunchContext) -> Sequence[Action]:
        actions = list(self.actions)
        if self.machine is not None:
            actions.insert(0, PushMachine(name=self.machine, where=self.where))
        if not resolve(context, self.scoped, Kind.BOOL, "scoped"):
            return actions
        keep = kept_configurations(context, self.keep)
        forwarding = resolve(context, self.forwarding, Kind.BOOL, "forwarding")
        return [PushScope(forwarding=forwarding, keep=keep), *actions, PopScope()]

    def sub_actions(self) -> Sequence[Action]:
        return self.actions
