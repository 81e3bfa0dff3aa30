"""`OpaqueFunction` (Python API only): call a function with the context at run time."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any

from launcher.description import made_by_code
from launcher.description.action import Action, LaunchDescriptionEntity
from launcher.errors import ExecutionError
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
        with made_by_code.writing(), context.process_environment():
            result = self.function(context, *self.args, **self.kwargs)
        return entities_of(result, "OpaqueFunction's function", self.function)


def entities_of(result: Any, what: str, function: Callable[..., Any]) -> list[Any] | None:
    """What user code returned, as the actions to visit: None, an action or description, or
    a list (any iterable) of them; anything else is said at the function's definition."""
    if result is None:
        return None
    if isinstance(result, LaunchDescriptionEntity):
        return [result]
    if isinstance(result, Iterable) and not isinstance(result, str | bytes | dict):
        items = list(result)
        wrong = [item for item in items if not isinstance(item, LaunchDescriptionEntity)]
        if not wrong:
            return items
        result = wrong[0]
    raise ExecutionError(f"{what} returned {result!r:.60} ({type(result).__name__}); "
                         "expected launch actions (a list of them, or None)",
                         made_by_code.defined_at(function))
