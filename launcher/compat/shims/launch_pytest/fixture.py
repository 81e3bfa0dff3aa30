"""launch_pytest.fixture: the decorator of launch fixtures, and the fixtures it widens."""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

import pytest

from launcher.compat.launch_fixtures import (
    GETTERS,
    OPTIONS,
    OVERRIDABLE,
    SCOPE,
    finalize,
    get_event_loop_fixture,
    get_launch_context_fixture,
    get_launch_service_fixture,
)

SCOPES = ("function", "class", "module", "package", "session")


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
    wait for it; a launch that failed fails the test, its message starting with `eprefix`."""
    finalize(launch_service, eprefix, auto_shutdown=auto_shutdown)


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


__all__ = ["finalize_launch_service", "fixture", "get_event_loop_fixture",
           "get_launch_context_fixture", "get_launch_service_fixture", "scope_gt"]
