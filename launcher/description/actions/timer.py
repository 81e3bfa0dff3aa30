"""`timer`: run children after `period` seconds, in the scope the timer was written in."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launcher.description.action import Action, Replay
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@action("timer")
@dataclass(kw_only=True, eq=False)
class TimerAction(Action):
    period: Any = attr(Kind.FLOAT, required=True, minimum=0, doc="Seconds to wait.")
    actions: list[Action] = attr(Kind.CHILDREN, doc="What to run when the time is up.")
    cancel_on_shutdown: Any = attr(Kind.BOOL, True,
                                   doc="Drop the timer if the launch shuts down first.")

    def execute(self, context: LaunchContext) -> None:
        service = context.service
        if service is None:
            return
        spec = type(self).__dataclass_fields__["period"].metadata["launch"]
        period = resolve(context, self.period, Kind.FLOAT, "period", spec)
        cancel = resolve(context, self.cancel_on_shutdown, Kind.BOOL, "cancel_on_shutdown")
        replay = Replay(snapshot=context.snapshot(), actions=list(self.actions))
        service.add_timer(period, lambda: service.schedule([replay]), cancel)

    def sub_actions(self) -> Sequence[Action]:
        return self.actions
