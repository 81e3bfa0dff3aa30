"""What a launch test file marks, and the loader and the runner read: post_shutdown_test (a
TestCase class that runs after the launch), parametrize (one launch per value),
ready_to_test_action_timeout, keep_alive (the launch is not ended when its processes are)
and retry_on_failure."""

from __future__ import annotations

import functools
import time
import unittest
from collections.abc import Callable, Iterator
from typing import Any


def post_shutdown_test() -> Callable[[type], type]:
    """Mark a TestCase class to run after the launch has ended (exit codes, all output)."""
    def decorate(case_class: type) -> type:
        if not isinstance(case_class, type):
            raise TypeError("post_shutdown_test should decorate test classes")
        case_class.__post_shutdown_test__ = True  # type: ignore[attr-defined]
        return case_class
    return decorate


def parametrize(argnames: str, argvalues: list[Any]) -> Callable[..., Any]:
    """Launch the test description once for each of `argvalues` (as pytest.mark.parametrize
    names them: "a, b" and tuples of values)."""
    names = [name.strip() for name in argnames.split(",") if name.strip()]
    rows = [value if isinstance(value, tuple) else (value,) for value in argvalues]

    def decorate(function: Callable[..., Any]) -> Callable[..., Any]:
        def variants() -> Iterator[tuple[Callable[..., Any], dict[str, Any]]]:
            for row in rows:
                args = dict(zip(names, row, strict=True))
                variant = functools.update_wrapper(functools.partial(function, **args),
                                                   function)
                yield variant, args

        variants.__parametrized__ = True  # type: ignore[attr-defined]
        for marker in ("__ready_to_test_action_timeout__", "__markers__"):
            if hasattr(function, marker):
                setattr(variants, marker, getattr(function, marker))
        return variants
    return decorate


def ready_to_test_action_timeout(timeout: float) -> Callable[..., Any]:
    """Wait `timeout` seconds (instead of 15) for the ReadyToTest action."""
    def decorate(function: Callable[..., Any]) -> Callable[..., Any]:
        function.__ready_to_test_action_timeout__ = timeout  # type: ignore[attr-defined]
        return function
    return decorate


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
