"""launch_testing.pytest.hookspecs: the hook a plugin implements to collect a launch test file
its own way."""

from __future__ import annotations

from typing import Any

import pytest


@pytest.hookspec(firstresult=True)
def pytest_launch_collect_makemodule(path: Any, parent: Any, entrypoint: Any) -> Any:
    """Make launch test module appropriate for the found test entrypoint."""
