"""launch_pytest.tools.process: wait for a process of the launch to start, to print what a
test expects (stdout, stderr: the action's `cached_output=True`), or to exit. Each has a
`_sync` form for plain tests and an async one for coroutines (run beside their loop). A
start or an exit that came before the call counts: it is not waited for again."""

from __future__ import annotations

import asyncio
import contextlib
import functools
from collections.abc import Callable, Iterator
from typing import Any

# the tools (launch_pytest.tools and .process give them; register_event_handler is .process's)
__all__ = ["assert_output", "assert_output_sync", "assert_stderr", "assert_stderr_sync",
           "wait_for_exit", "wait_for_exit_sync", "wait_for_output", "wait_for_output_sync",
           "wait_for_start", "wait_for_start_sync", "wait_for_stderr", "wait_for_stderr_sync"]


@contextlib.contextmanager
def register_event_handler(context: Any, event_handler: Any) -> Iterator[None]:
    """`event_handler` is one of the launch's (`context`: launch_context) inside the block."""
    try:
        yield context.register_event_handler(event_handler, append=True)
    finally:
        context.unregister_event_handler(event_handler)


def wait_for_start_sync(launch_context: Any, execute_process_action: Any,
                        timeout: float | None = None) -> bool:
    """Whether the action's process started within `timeout` seconds."""
    return bool(launch_context.until(
        lambda: launch_context.has_started(execute_process_action), timeout))


def wait_for_exit_sync(launch_context: Any, execute_process_action: Any,
                       timeout: float | None = None) -> bool:
    """Whether the action's process exited within `timeout` seconds."""
    return bool(launch_context.until(
        lambda: launch_context.has_exited(execute_process_action), timeout))


def wait_for_output_sync(launch_context: Any, execute_process_action: Any,
                         validate_output: Callable[[str], Any],
                         timeout: float | None = None) -> Any:
    """`validate_output(all of stdout)` once true, or its value when `timeout` ran out."""
    return launch_context.until(
        lambda: validate_output(execute_process_action.get_stdout()), timeout)


def wait_for_stderr_sync(launch_context: Any, execute_process_action: Any,
                         validate_output: Callable[[str], Any],
                         timeout: float | None = None) -> Any:
    """As wait_for_output_sync, on stderr."""
    return launch_context.until(
        lambda: validate_output(execute_process_action.get_stderr()), timeout)


def assert_output_sync(launch_context: Any, execute_process_action: Any,
                       validate_output: Callable[[str], Any],
                       timeout: float | None = None) -> None:
    """Wait until `validate_output` passes on stdout (it asserts, or returns a boolean); its
    assertion if it never does."""
    _assert(wait_for_output_sync, launch_context, execute_process_action, validate_output,
            timeout, execute_process_action.get_stdout, "stdout")


def assert_stderr_sync(launch_context: Any, execute_process_action: Any,
                       validate_output: Callable[[str], Any],
                       timeout: float | None = None) -> None:
    """As assert_output_sync, on stderr."""
    _assert(wait_for_stderr_sync, launch_context, execute_process_action, validate_output,
            timeout, execute_process_action.get_stderr, "stderr")


def _assert(wait: Callable[..., Any], launch_context: Any, action: Any,
            validate: Callable[[str], Any], timeout: float | None,
            read: Callable[[], str], stream: str) -> None:
    """A validator that returns False fails too (launch_pytest's passes it: only an
    AssertionError counts there, though its examples say a boolean may be returned)."""
    def passes(text: str) -> bool:
        try:
            return validate(text) is not False
        except AssertionError:
            return False

    if not wait(launch_context, action, passes, timeout):
        text = read()
        if validate(text) is False:  # (one that asserts has raised its own message)
            raise AssertionError(f"the {stream} of {_name(action)} did not pass "
                                 f"{getattr(validate, '__name__', 'the check')} within "
                                 f"{timeout} s; it was:\n{text}")


def _name(action: Any) -> str:
    details = getattr(action, "process_details", None) or {}
    return details.get("name") or type(action).__name__


def _beside_the_loop(function: Callable[..., Any]) -> Callable[..., Any]:
    """The async form of a `_sync` wait: run in the loop's executor, the loop free."""
    @functools.wraps(function)
    async def wait(*args: Any, **kwargs: Any) -> Any:
        return await asyncio.get_running_loop().run_in_executor(
            None, functools.partial(function, *args, **kwargs))
    wait.__name__ = wait.__qualname__ = function.__name__.removesuffix("_sync")
    return wait


wait_for_start = _beside_the_loop(wait_for_start_sync)
wait_for_exit = _beside_the_loop(wait_for_exit_sync)
wait_for_output = _beside_the_loop(wait_for_output_sync)
wait_for_stderr = _beside_the_loop(wait_for_stderr_sync)
assert_output = _beside_the_loop(assert_output_sync)
assert_stderr = _beside_the_loop(assert_stderr_sync)
