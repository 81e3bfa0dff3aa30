"""launch_testing.markers: keep_alive (the launch is not ended when its processes are) and
retry_on_failure."""

from __future__ import annotations

import functools
import time
import unittest
from collections.abc import Callable
from typing import Any


def keep_alive(test_description: Callable[..., Any]) -> Callable[..., Any]:
    """The launch stays up when every process under test has ended, until the active tests
    are done."""
    markers = getattr(test_description, "__markers__", None) or {}
    markers["keep_alive"] = True
    test_description.__markers__ = markers  # type: ignore[attr-defined]
    return test_description


def retry_on_failure(*, times: int, delay: float | None = None) -> Callable[..., Any]:
    """Run a test method again, up to `times` in all, while it fails an assertion."""
    if times <= 0:
        raise ValueError(f"retry_on_failure: times must be > 0, got {times}")

    def decorate(method: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(method)
        def retried(self: unittest.TestCase, *args: Any, **kwargs: Any) -> Any:
            for _ in range(times - 1):
                try:
                    return method(self, *args, **kwargs)
                except AssertionError:
                    if delay:
                        time.sleep(delay)
            return method(self, *args, **kwargs)
        return retried
    return decorate


__all__ = ["keep_alive", "retry_on_failure"]
