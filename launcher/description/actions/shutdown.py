"""`shutdown`: end the launch."""

from __future__ import annotations

from launcher.description.action import Action
from launcher.description.fields import Kind, attr
from launcher.description.registry import action
from launcher.description.substitution import Text_, perform_text
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@action("shutdown")
@dataclass(kw_only=True, eq=False)
class Shutdown(Action):
    reason: Text_ | None = attr(Kind.TEXT, doc="Why the launch ends (shown in the log).")

    def execute(self, context: LaunchContext) -> None:
        reason = "shutdown requested" if self.reason is None else perform_text(context,
                                                                              self.reason)
        if context.service is not None:
            if not context.service.shutting_down:  # said once, for the first reason
                context.service.log("INFO", "launch", f"shutting down: {reason}")
            context.service.shutdown(reason)
