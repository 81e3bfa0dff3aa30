"""`OpaqueFunction` (Python API only): call a function with the context at run time."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launcher.description.action import Action
from launcher.records import dataclass, field
from launcher.runtime.context import LaunchContext


@dataclass(kw_only=True, eq=False)
class OpaqueFunction(Action):
    function: Callable[..., Sequence[Action] | None]
    args: Sequence[Any] = ()
    kwargs: dict[str, Any] = field(default_factory=dict)

    def __init__(self, function: Callable[..., Any], args: Sequence[Any] = (),
                 kwargs: dict[str, Any] | None = None, **rest: Any) -> None:
        self.function, self.args, self.kwargs = function, args, dict(kwargs or {})
        self.condition, self.where = rest.get("condition"), rest.get("where")

    def execute(self, context: LaunchContext) -> Sequence[Action] | None:
        result = self.function(context, *self.args, **self.kwargs)
        return list(result) if result else None
