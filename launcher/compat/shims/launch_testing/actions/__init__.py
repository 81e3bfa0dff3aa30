"""launch_testing.actions: ReadyToTest, the action that says the tests may start, and the
actions that run a test program (GTest, PyTest)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launch_testing.actions.gtest import GTest
from launch_testing.actions.pytest import PyTest
from launcher.api import Action


class ReadyToTest(Action):
    """Visited, it tells the test runner that the processes before it have started and the
    active tests may begin."""

    def __init__(self, **kwargs: Any) -> None:
        self.condition, self.where = kwargs.get("condition"), kwargs.get("where")
        self.callbacks: list[Callable[[], None]] = []

    def add_callback(self, callback: Callable[[], None]) -> None:
        self.callbacks.append(callback)

    _add_callback = add_callback  # (launch_testing's own name, which its tools call)

    def execute(self, context: Any) -> Sequence[Action] | None:
        for callback in self.callbacks:
            callback()
        return None


__all__ = ["GTest", "PyTest", "ReadyToTest"]
