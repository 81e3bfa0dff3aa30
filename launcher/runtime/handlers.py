"""The launch's event handlers (OnProcessExit, OnShutdown, …): each event goes to those that
match it, and the actions they return are queued for visiting."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launcher.runtime import events


class Handlers:
    def __init__(self, context: Any, guarded: Callable[[Callable[[], Any], Any], Any],
                 schedule: Callable[[Sequence[Any]], None]) -> None:
        """`guarded(run, where)` runs a handler's callback so that its failure ends the
        launch; `schedule` queues the actions it returns."""
        self.context, self.guarded, self.schedule = context, guarded, schedule
        self.registered: list[events.EventHandler] = []

    def register(self, handler: events.EventHandler) -> None:
        self.registered.append(handler)

    def unregister(self, handler: events.EventHandler) -> None:
        if handler in self.registered:
            self.registered.remove(handler)

    def would_handle(self, event: events.Event) -> bool:
        return any(handler.matches(event) for handler in self.registered)

    def emit(self, event: events.Event) -> None:
        for handler in list(self.registered):
            if handler.matches(event):
                actions = self.guarded(lambda h=handler: h.handle(event, self.context), None)
                if actions:
                    self.schedule(actions)
