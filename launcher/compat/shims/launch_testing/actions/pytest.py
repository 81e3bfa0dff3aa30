"""launch_testing.actions.PyTest: `python -m pytest PATH` run as a Test."""

from __future__ import annotations

import sys
from typing import Any

from launch_testing.actions.test import Test


class PyTest(Test):
    """Runs pytest on `path` with this interpreter (Test's and ExecuteProcess's other
    arguments)."""

    def __init__(self, *, path: Any, **kwargs: Any) -> None:
        super().__init__(cmd=[sys.executable, "-m", "pytest", path], **kwargs)
        self._path = path

    @property
    def path(self) -> Any:
        return self._path


__all__ = ["PyTest", "Test"]
