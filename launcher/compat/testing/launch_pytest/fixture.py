"""launch_pytest's fixtures: `@launch_pytest.fixture` (a launch description that tests run
beside), and the fixtures it widens, each made for a scope: `event_loop` (the asyncio loop
async tests run on), `launch_service` (a launch run in a thread of its own,
threaded_launch.py) and `launch_context` (what the process tools wait on). The launch service
itself is made by the plugin that runs the tests (its factory in the config's stash: the
workspace's hooks, the graph)."""

from __future__ import annotations

import asyncio
import sys
from collections.abc import Callable, Iterator
from typing import Any

import pytest

from launcher.compat.testing.launch_pytest.threaded_launch import ThreadedLaunch

NEW_SERVICE: Any = pytest.StashKey()  # the config's factory of launch services
# the pytest sessions configured, innermost last (pytester nests them); launcher's plugin
# (pytest_plugin.py) keeps it, so that launch_service takes event_loop alone, as
# launch_pytest's does
CONFIGS: list[Any] = []
OPTIONS = "_launch_pytest_fixture_options"  # on a launch fixture: how its launch runs
OVERRIDABLE = "_launch_pytest_overridable_fixture"
SCOPE = "_launch_pytest_fixture_scope"
SCOPES = ("function", "class", "module", "package", "session")


def _mark(fixture: Any, scope: str, overridable: bool) -> Any:
    if overridable:
        setattr(fixture, OVERRIDABLE, True)
        setattr(fixture, SCOPE, scope)
    return fixture


def get_event_loop_fixture(*, scope: str = "function", overridable: bool = True) -> Any:
    """An `event_loop` fixture of `scope`: a new asyncio loop, closed after."""
    @pytest.fixture(scope=scope)
    def event_loop() -> Iterator[asyncio.AbstractEventLoop]:
        loop = asyncio.new_event_loop()
        asyncio.set_event_loop(loop)
        yield loop
        loop.close()
        asyncio.set_event_loop(None)
    return _mark(event_loop, scope, overridable)


def get_launch_service_fixture(*, scope: str = "function", overridable: bool = True) -> Any:
    """A `launch_service` fixture of `scope`: a launch, ended (and checked) after."""
    @pytest.fixture(scope=scope)
    def launch_service(event_loop: Any) -> Iterator[ThreadedLaunch]:
        if not CONFIGS:
            raise RuntimeError("launch_service: launcher's pytest plugin "
                               "(launcher.compat.testing.pytest_plugin) is not loaded")
        new_service: Callable[[], Any] = CONFIGS[-1].stash[NEW_SERVICE]
        launch = ThreadedLaunch(new_service, event_loop)
        yield launch
        finalize_launch_service(launch, "When tearing down launch_service fixture")
    return _mark(launch_service, scope, overridable)


def get_launch_context_fixture(*, scope: str = "function", overridable: bool = True) -> Any:
    """A `launch_context` fixture of `scope`: the launch's, for the process tools."""
    @pytest.fixture(scope=scope)
    def launch_context(launch_service: ThreadedLaunch) -> Any:
        return launch_service.context
    return _mark(launch_context, scope, overridable)


GETTERS = {"launch_service": get_launch_service_fixture, "event_loop": get_event_loop_fixture,
           "launch_context": get_launch_context_fixture}


def fixture(decorated: Callable[..., Any] | None = None, *args: Any,
            shutdown_when_idle: bool = True, auto_shutdown: bool = True,
            **kwargs: Any) -> Any:
    """Make a launch fixture: a pytest fixture (same arguments) returning a
    LaunchDescription, or a sequence whose first item is one.

    `shutdown_when_idle`: the launch ends once nothing runs in it; `auto_shutdown`: it is
    shut down once the tests that run beside it are done (else it must end by itself). A scope
    wider than a function gives the module `launch_service`, `event_loop` and
    `launch_context` fixtures of that scope, unless it defines its own."""
    scope = kwargs.get("scope", "function")
    if scope != "function":
        _widen(sys._getframe(1).f_globals, scope)

    def decorate(function: Callable[..., Any]) -> Any:
        options = {"shutdown_when_idle": shutdown_when_idle, "auto_shutdown": auto_shutdown,
                   "scope": scope}
        setattr(function, OPTIONS, options)
        definition = pytest.fixture(*args, **kwargs)(function)
        setattr(definition, OPTIONS, options)
        return definition
    return decorate if decorated is None else decorate(decorated)


def finalize_launch_service(launch_service: Any, eprefix: str = "",
                            auto_shutdown: bool = True) -> None:
    """End the launch `launch_service` runs (shut it down first if `auto_shutdown`) and
    wait for it; a launch that failed (an action, not a process's exit status: that is the
    tests' to judge) fails the test, its message starting with `eprefix`."""
    launch_service.finish(auto_shutdown=auto_shutdown)
    if launch_service.failed:
        pytest.fail(f"{eprefix} launch service failed when finishing: an action of the launch "
                    "failed (its error is printed above)", pytrace=False)


def scope_gt(scope1: str, scope2: str) -> bool:
    """Whether pytest scope `scope1` is wider than `scope2` ('module' > 'function')."""
    from _pytest.scope import Scope

    return Scope(scope1) > Scope(scope2)


def _widen(module: dict[str, Any], scope: str) -> None:
    if scope not in SCOPES:
        return
    for name, getter in GETTERS.items():
        present = module.get(name)
        if present is None or getattr(present, OVERRIDABLE, False) and \
                scope_gt(scope, getattr(present, SCOPE)):
            module[name] = getter(scope=scope)
