"""rclpy.guard_condition.GuardCondition: trigger() runs its callback on the executor."""

from __future__ import annotations

from typing import Any


class GuardCondition:
    def __init__(self, callback: Any, callback_group: Any, host: Any, run: Any = None) -> None:
        """`host` queues its work; `run` is the callback as its group runs it (the node's)."""
        self.callback, self.callback_group, self._host = callback, callback_group, host
        self._run = run

    def trigger(self) -> None:
        """Run the callback once, on the node's executor."""
        if self._host is not None and self._run is not None:
            self._host.enqueue(self._run)

    def destroy(self) -> None:
        """Stop: a later trigger runs nothing."""
        self._host = None
