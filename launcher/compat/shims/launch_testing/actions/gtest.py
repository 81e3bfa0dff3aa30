"""launch_testing.actions.GTest: a GoogleTest program run as a Test."""

from __future__ import annotations

from typing import Any

from launch_testing.actions.test import Test


class GTest(Test):
    """Runs the program at `path` (Test's and ExecuteProcess's other arguments)."""

    def __init__(self, *, path: Any, **kwargs: Any) -> None:
        super().__init__(cmd=[path], **kwargs)
        self._path = path

    @property
    def path(self) -> Any:
        return self._path


__all__ = ["GTest", "Test"]
