"""launch_pytest's fixtures: `event_loop` (the asyncio loop async tests run on),
`launch_service` (a launch run in a thread of its own, threaded_launch.py) and
`launch_context` (what the process tools wait on), each made for a scope. The launch service
itself is made by the plugin that runs the tests (its factory in the config's stash: the
workspace's hooks, the graph)."""

from __future__ import annotations

import asyncio
from collections.abc import Callable, Iterator
from typing import Any

import pytest

from launcher.compat.threaded_launch import ThreadedLaunch

NEW_SERVICE: Any = pytest.StashKey()  # the config's factory of launch services
# the pytest sessions configured, innermost last (pytester nests them); launcher's plugin
# (compat/pytest_plugin.py) keeps it, so that launch_service takes event_loop alone, as
# launch_pytest's does
CONFIGS: list[Any] = []
OPTIONS = "_launch_pytest_fixture_options"  # on a launch fixture: how its launch runs
OVERRIDABLE = "_launch_pytest_overridable_fixture"
SCOPE = "_launch_pytest_fixture_scope"


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
                               "(launcher.compat.pytest_plugin) is not loaded")
        new_service: Callable[[], Any] = CONFIGS[-1].stash[NEW_SERVICE]
        launch = ThreadedLaunch(new_service, event_loop)
        yield launch
        finalize(launch, "When tearing down launch_service fixture")
    return _mark(launch_service, scope, overridable)


def get_launch_context_fixture(*, scope: str = "function", overridable: bool = True) -> Any:
    """A `launch_context` fixture of `scope`: the launch's, for the process tools."""
    @pytest.fixture(scope=scope)
    def launch_context(launch_service: ThreadedLaunch) -> Any:
        return launch_service.context
    return _mark(launch_context, scope, overridable)


GETTERS = {"launch_service": get_launch_service_fixture, "event_loop": get_event_loop_fixture,
           "launch_context": get_launch_context_fixture}


def finalize(launch: ThreadedLaunch, prefix: str, *, auto_shutdown: bool = True) -> None:
    """End the launch (shut down first unless it is to end by itself); a launch that failed
    (an action, not a process's exit status: that is the tests' to judge) fails here."""
    launch.finish(auto_shutdown=auto_shutdown)
    if launch.failed:
        pytest.fail(f"{prefix} launch service failed when finishing: an action of the launch "
                    "failed (its error is printed above)", pytrace=False)
