"""rclpy.guard_condition.GuardCondition: trigger() runs its callback on the executor."""

from __future__ import annotations

from typing import Any

from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.context import Context, get_default_context  # noqa: F401


class GuardCondition:
    def __init__(self, callback: Any, callback_group: Any, context: Context | None = None, *,
                 host: Any = None, run: Any = None) -> None:
        """`host` queues its work and `run` is the callback as its group runs it (a node's
        guard conditions have both; one without runs nothing when triggered)."""
        self.callback, self.callback_group = callback, callback_group
        self.context = context or get_default_context()
        self._host, self._run = host, run
        self.triggered = False

    def trigger(self) -> None:
        """Run the callback once, on the node's executor."""
        self.triggered = True
        if self._host is not None and self._run is not None:
            self._host.enqueue(self._run)

    def destroy(self) -> None:
        """Stop: a later trigger runs nothing."""
        self._host = None

    def __enter__(self) -> GuardCondition:
        return self

    def __exit__(self, *exc: Any) -> None:
        pass
