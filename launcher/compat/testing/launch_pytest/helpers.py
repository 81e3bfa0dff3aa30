"""launch_pytest.plugin's helpers: they read the marks and items that launcher's plugin
(plugin.py) reads, and run a test's function, coroutine or generator on an asyncio loop as
launch_pytest's wrappers do; and the plugin module's own fixtures."""

from __future__ import annotations

import asyncio
import functools
import inspect
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Any

import pytest

from launcher.compat.testing.actions import ReadyToTest
from launcher.compat.testing.launch_pytest.fixture import (
    OPTIONS,
    get_event_loop_fixture,
    get_launch_context_fixture,
    get_launch_service_fixture,
)
from launcher.compat.testing.launch_pytest.plugin import MARK

SHUTDOWN = "_launch_pytest_shutdown"  # on an item: it runs after its launch has ended


class LaunchTestWarning(pytest.PytestWarning):
    """Raised in this plugin to warn users."""


def transfer_markers(*args: Any, **kwargs: Any) -> None:
    """Nothing to do: pytest (4.1 on) applies a module's marks itself."""


# --- the launch description -----------------------------------------------------------------
def iterate_ready_to_test_actions(entities: Iterable[Any]) -> Iterator[Any]:
    """Every ReadyToTest among `entities` and theirs, conditional ones included."""
    for entity in entities:
        if isinstance(entity, ReadyToTest):
            yield entity
        yield from iterate_ready_to_test_actions(entity.describe_sub_entities())
        for _, conditional in entity.describe_conditional_sub_entities():
            yield from iterate_ready_to_test_actions(conditional)


def get_ready_to_test_action(launch_description: Any) -> Any:
    """The description's one ReadyToTest (one is added at its end when it has none; a
    RuntimeError when it has more)."""
    found = list(iterate_ready_to_test_actions(launch_description.entities))
    if len(found) > 1:
        raise RuntimeError("launch_pytest fixtures must return a LaunchDescription containing "
                           "only one ReadyToTest action")
    if found:
        return found[0]
    ready = ReadyToTest()
    launch_description.add_action(ready)
    return ready


# --- the items ----------------------------------------------------------------------------
def is_launch_test(item: Any) -> bool:
    return item.get_closest_marker(MARK) is not None


def is_launch_test_mark_valid(item: Any) -> bool:
    """Its launch mark names a fixture."""
    return item.get_closest_marker(MARK).kwargs.get("fixture") is not None


def has_shutdown_kwarg(item: Any) -> bool:
    return bool(item.get_closest_marker(MARK).kwargs.get("shutdown", False))


def get_launch_test_fixture(item: Any) -> Any:
    """The launch fixture of the item's mark (None: not a launch test)."""
    mark = item.get_closest_marker(MARK)
    return None if mark is None else mark.kwargs.get("fixture")


def get_launch_test_fixturename(item: Any) -> str | None:
    fixture = get_launch_test_fixture(item)
    return None if fixture is None else fixture.__name__


def is_valid_test_item(obj: Any) -> bool:
    """A function, coroutine, generator or async generator function."""
    return inspect.isfunction(obj) or inspect.iscoroutinefunction(obj) or \
        inspect.isgeneratorfunction(obj) or inspect.isasyncgenfunction(obj)


def need_shutdown_test_item(obj: Any) -> bool:
    """A generator's part after its yield is a test of its own (run after the launch)."""
    return inspect.isgeneratorfunction(obj) or inspect.isasyncgenfunction(obj)


def is_shutdown_test(item: Any) -> bool:
    return bool(getattr(item, SHUTDOWN, False))


def is_same_launch_test_fixture(left_item: Any, right_item: Any) -> bool:
    """Both use the same launch fixture, wider than a function, with the same parameters."""
    fixture = get_launch_test_fixture(left_item)
    if fixture is None or fixture is not get_launch_test_fixture(right_item):
        return False
    if getattr(fixture, OPTIONS, {}).get("scope", "function") == "function":
        return False

    def params(item: Any) -> Any:
        callspec = getattr(item, "callspec", None)
        return None if callspec is None else callspec.params.get(fixture.__name__)
    return params(left_item) == params(right_item)


def from_parent(cls: Any, *args: Any, **kwargs: Any) -> Any:
    return cls.from_parent(*args, **kwargs)


# --- running a test on the loop -------------------------------------------------------------
def run_until_complete(loop: asyncio.AbstractEventLoop, future_like: Any) -> Any:
    """loop.run_until_complete, the future's exception retrieved when it fails (no 'never
    retrieved' warning)."""
    try:
        return loop.run_until_complete(future_like)
    except BaseException:
        if future_like.done() and not future_like.cancelled():
            future_like.exception()
        raise


def wrap_coroutine(func: Callable[..., Any], event_loop: Any, before_test: Any) -> Any:
    """A plain function that runs the coroutine `func` on `event_loop` (after
    `before_test`, when given)."""
    @functools.wraps(func)
    def inner(**kwargs: Any) -> None:
        if before_test is not None:
            before_test()
        run_until_complete(event_loop, asyncio.ensure_future(func(**kwargs), loop=event_loop))
    return inner


def wrap_func(func: Callable[..., Any], event_loop: Any, before_test: Any) -> Any:
    """A function that runs `func` in the loop's executor while the loop runs."""
    @functools.wraps(func)
    def inner(**kwargs: Any) -> None:
        if before_test is not None:
            before_test()
        future = event_loop.run_in_executor(None, functools.partial(func, **kwargs))
        run_until_complete(event_loop, future)
    return inner


@dataclass(frozen=True)
class _Steps:
    """How a kind of generator is stepped on the loop: `start` runs it up to its yield;
    `resume`, after the launch's end, must end it by raising `stop`."""
    start: Callable[[Any], None]
    resume: Callable[[Any], None]
    stop: type[BaseException]
    what: str  # in the message when it yields again

    def finish(self, generator: Any) -> None:
        """The part after the yield: it must end there."""
        try:
            self.resume(generator)
        except self.stop:
            return
        pytest.fail(f"launch tests using {self.what} must stop iteration after yielding once",
                    pytrace=False)


def _generator_steps(event_loop: Any) -> _Steps:
    return _Steps(lambda generator: run_until_complete(
                      event_loop, event_loop.run_in_executor(None, next, generator)),
                  next, StopIteration, "a generator function")


def _asyncgen_steps(event_loop: Any) -> _Steps:
    def step(agen: Any) -> None:
        run_until_complete(event_loop, asyncio.ensure_future(agen.__anext__(), loop=event_loop))
    return _Steps(step, step, StopAsyncIteration, "an async gen function")


def _two_tests(func: Callable[..., Any], steps: _Steps,
               on_shutdown: Callable[[], Any]) -> tuple[Any, Any]:
    """`func`'s generator as two tests: up to its yield, and after the launch's end."""
    started: list[Any] = []

    def shutdown(**kwargs: Any) -> None:
        if not started:
            pytest.skip("shutdown test skipped because the test failed before")
        on_shutdown()
        steps.finish(started[0])
    shutdown._launch_pytest_wrapped = True  # type: ignore[attr-defined]
    shutdown.__name__ = f"{func.__name__}[shutdown]"

    @functools.wraps(func)
    def inner(**kwargs: Any) -> None:
        generator = func(**kwargs)
        steps.start(generator)
        started.append(generator)
    return inner, shutdown


def _one_test(func: Callable[..., Any], steps: _Steps, on_shutdown: Callable[[], Any]) -> Any:
    """`func`'s generator as one test: up to its yield, the launch's end, the rest."""
    @functools.wraps(func)
    def inner(**kwargs: Any) -> None:
        generator = func(**kwargs)
        steps.start(generator)
        on_shutdown()
        steps.finish(generator)
    return inner


def wrap_generator(func: Callable[..., Any], event_loop: Any,
                   on_shutdown: Callable[[], Any]) -> tuple[Any, Any]:
    """The generator `func` as two tests: up to its yield, and after the launch's end."""
    return _two_tests(func, _generator_steps(event_loop), on_shutdown)


def wrap_generator_fscope(func: Callable[..., Any], event_loop: Any,
                          on_shutdown: Callable[[], Any]) -> Any:
    """The generator `func` as one test: up to its yield, the launch's end, the rest."""
    return _one_test(func, _generator_steps(event_loop), on_shutdown)


def wrap_asyncgen(func: Callable[..., Any], event_loop: Any,
                  on_shutdown: Callable[[], Any]) -> tuple[Any, Any]:
    """The async generator `func` as two tests, as wrap_generator."""
    return _two_tests(func, _asyncgen_steps(event_loop), on_shutdown)


def wrap_asyncgen_fscope(func: Callable[..., Any], event_loop: Any,
                         on_shutdown: Callable[[], Any]) -> Any:
    """The async generator `func` as one test, as wrap_generator_fscope."""
    return _one_test(func, _asyncgen_steps(event_loop), on_shutdown)


launch_service = get_launch_service_fixture(overridable=False)
launch_context = get_launch_context_fixture(overridable=False)
event_loop = get_event_loop_fixture(overridable=False)
