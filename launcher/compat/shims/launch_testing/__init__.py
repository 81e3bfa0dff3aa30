"""launch_testing over launcher's launch service: a test file's `generate_test_description`
is launched, its active tests run while it runs, its post-shutdown tests after it ends
(`launch_test FILE`, `ros2 test FILE`, `python -m launch_testing.launch_test FILE`, or plain
`pytest FILE`). A real launch_testing that the user installed wins in their shell."""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from typing import Any

from launch_testing import actions, asserts, markers, tools, util
from launch_testing.io_handler import ActiveIoHandler, IoHandler
from launch_testing.proc_info_handler import ActiveProcInfoHandler, ProcInfoHandler
from launch_testing.ready_aggregator import ReadyAggregator


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


__all__ = ["ActiveIoHandler", "ActiveProcInfoHandler", "IoHandler", "ProcInfoHandler",
           "ReadyAggregator",
           "actions", "asserts", "markers", "parametrize", "post_shutdown_test",
           "ready_to_test_action_timeout", "tools", "util"]
