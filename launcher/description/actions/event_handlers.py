"""Event handlers: run actions when a process starts, exits or prints, or at shutdown.

The Python API's `RegisterEventHandler(OnProcessExit(target_action=…, on_exit=[…]))`, and the
frontends' `on_exit` / `on_start` children of `executable` and `node`, both end up here.
Handler actions run in the scope in which the handler was registered.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launcher.description.action import Action, Replay
from launcher.records import dataclass, field
from launcher.runtime import events
from launcher.runtime.context import LaunchContext, Snapshot

Reaction = Sequence[Action] | Callable[..., Sequence[Action] | Action | None]


@dataclass
class Handler:
    event_type: type = field(init=False, default=object)
    target_action: Any = None
    snapshot: Snapshot | None = field(default=None, repr=False)

    def matches(self, event: Any) -> bool:
        if not isinstance(event, self.event_type):
            return False
        return self.target_action is None or getattr(event, "origin", None) is self.target_action

    def reaction(self, event: Any) -> Reaction | None:
        raise NotImplementedError

    def handle(self, event: Any, context: LaunchContext) -> Sequence[Action] | None:
        what = self.reaction(event)
        if what is None:
            return None
        actions = what(event, context) if callable(what) else what
        if actions is None:
            return None
        if isinstance(actions, Action):
            actions = [actions]
        snapshot = self.snapshot or context.snapshot()
        return [Replay(snapshot=snapshot, actions=list(actions))]


@dataclass
class OnProcessStart(Handler):
    on_start: Reaction | None = None

    def __post_init__(self) -> None:
        self.event_type = events.ProcessStarted

    def reaction(self, event: Any) -> Reaction | None:
        return self.on_start


@dataclass
class OnProcessExit(Handler):
    on_exit: Reaction | None = None

    def __post_init__(self) -> None:
        self.event_type = events.ProcessExited

    def reaction(self, event: Any) -> Reaction | None:
        return self.on_exit


@dataclass
class OnProcessIO(Handler):
    on_stdout: Callable[..., Any] | None = None
    on_stderr: Callable[..., Any] | None = None

    def __post_init__(self) -> None:
        self.event_type = events.ProcessIO

    def reaction(self, event: Any) -> Reaction | None:
        return self.on_stdout if event.stream == "stdout" else self.on_stderr


@dataclass
class OnShutdown(Handler):
    on_shutdown: Reaction | None = None

    def __post_init__(self) -> None:
        self.event_type = events.Shutdown

    def reaction(self, event: Any) -> Reaction | None:
        return self.on_shutdown


@dataclass(kw_only=True, eq=False)
class RegisterEventHandler(Action):
    event_handler: Handler

    def __init__(self, event_handler: Handler, **kwargs: Any) -> None:
        self.event_handler = event_handler
        self.condition = kwargs.get("condition")
        self.where = kwargs.get("where")

    def execute(self, context: LaunchContext) -> None:
        if context.service is None:
            return
        self.event_handler.snapshot = context.snapshot()
        context.service.register_handler(self.event_handler)
