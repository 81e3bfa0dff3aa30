"""launch_pytest's pytest plugin, as launcher's. A test marked
`@pytest.mark.launch(fixture=F)` runs while the launch F describes is running (F is a
`@launch_pytest.fixture`), or after it has ended with `shutdown=True`; a generator test runs
up to its `yield` beside the launch and the rest after it; coroutines run on the `event_loop`
fixture's loop. The launch runs in a thread of its own (threaded_launch.py) on a graph
of its own for the pytest session (a private run folder, its router and nodes gone with it).

Where a real launch_pytest is installed, its own plugin runs the tests and this one stands
aside."""

from __future__ import annotations

import inspect
from collections.abc import Callable, Sequence
from typing import Any

import pytest

from launcher import compat
from launcher.api import LaunchDescription
from launcher.compat.testing.actions import ReadyToTest
from launcher.compat.testing.launch_pytest.fixture import (
    NEW_SERVICE,
    OPTIONS,
    get_event_loop_fixture,
    get_launch_context_fixture,
    get_launch_service_fixture,
)
from launcher.compat.testing.loader import ready_actions

MARK = "launch"
READY_TIMEOUT = "launch_pytest_ready_timeout"  # the ini option: s a launch is given to be ready
ACTIVE = not compat.installed_apart("launch_pytest")


def pytest_addoption(parser: Any) -> None:
    if ACTIVE:
        parser.addini(READY_TIMEOUT, "seconds a launch_pytest fixture's launch is given to "
                                     "reach its ReadyToTest (default: 60)", default="60")


def pytest_configure(config: Any) -> None:
    if not ACTIVE:
        return
    config.addinivalue_line("markers", f"{MARK}(fixture, shutdown=False): a test run beside "
                                       "the launch its launch_pytest fixture describes")
    config.stash[NEW_SERVICE] = _SessionGraph()


def pytest_unconfigure(config: Any) -> None:
    graph = config.stash.get(NEW_SERVICE, None)
    if isinstance(graph, _SessionGraph):
        graph.close()


class _SessionGraph:
    """Makes the session's launch services, all on one graph of the session's own (made at the
    first: a pytest run with no launch tests changes nothing)."""

    def __init__(self) -> None:
        self._graph: Any = None

    def __call__(self) -> Any:
        from launcher.cli.launch_command import launch_service
        from launcher.cli.own_graph import own_graph
        from launcher.cli.workspace import load_index

        if self._graph is None:
            self._graph = own_graph("launch-pytest-")
            self._graph.__enter__()
        return launch_service({}, load_index())

    def close(self) -> None:
        if self._graph is not None:
            self._graph.__exit__(None, None, None)
            self._graph = None


def pytest_pycollect_makemodule(module_path: Any, parent: Any) -> None:
    """A test file that imports launch_pytest imports launch, rclpy, … too: the shims and the
    node APIs are made importable first (nothing changes for other files)."""
    if ACTIVE and module_path.suffix == ".py" and _imports(module_path, "launch_pytest"):
        compat.enable_in_process()


def _imports(path: Any, name: str) -> bool:
    import ast

    try:
        tree = ast.parse(path.read_text(errors="replace"))
    except (OSError, SyntaxError, ValueError):
        return False
    for node in tree.body:
        if isinstance(node, ast.Import) and any(a.name.split(".")[0] == name
                                                for a in node.names):
            return True
        if isinstance(node, ast.ImportFrom) and (node.module or "").split(".")[0] == name:
            return True
    return False


# --- the fixtures: a function's scope unless a launch fixture widens them ------------------
if ACTIVE:
    launch_service = get_launch_service_fixture(overridable=False)
    launch_context = get_launch_context_fixture(overridable=False)
    event_loop = get_event_loop_fixture(overridable=False)


@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_fixture_setup(fixturedef: Any, request: Any) -> Any:
    """A launch fixture's description is launched, and the test waits for its ReadyToTest."""
    options = getattr(fixturedef.func, OPTIONS, None) if ACTIVE else None
    if options is None:
        return (yield)
    where = f"When running launch_pytest fixture '{fixturedef.argname}'"
    launch = request.getfixturevalue("launch_service")
    result = yield
    description = _description(result, where)
    ready = _ready_action(description, where)
    fixturedef.addfinalizer(lambda: launch.finish(auto_shutdown=options["auto_shutdown"]))
    launch.start(description, ready, shutdown_when_idle=options["shutdown_when_idle"])
    timeout = float(request.config.getini(READY_TIMEOUT))
    if not launch.wait_ready(timeout):
        reason = "the launch ended first" if launch.ended else \
            f"it was not reached in {timeout:g} s ({READY_TIMEOUT} in the pytest configuration)"
        launch.finish()
        pytest.fail(f"{where}: ReadyToTest was never reached: {reason}", pytrace=False)
    return result


def _description(value: Any, where: str) -> Any:
    description = value[0] if isinstance(value, Sequence) and value else value
    if not isinstance(description, LaunchDescription):
        pytest.fail(f"{where}: return value must be either a launch description or a sequence "
                    f"which first item is a launch description (it returned "
                    f"{type(value).__name__})", pytrace=False)
    return description


def _ready_action(description: Any, where: str) -> Any:
    """Its one ReadyToTest; one is added at its end when it has none."""
    found = list(ready_actions(description.actions))
    if len(found) > 1:
        pytest.fail(f"{where}: launch_pytest fixtures must return a LaunchDescription "
                    f"containing only one ReadyToTest action (it has {len(found)})",
                    pytrace=False)
    if found:
        return found[0]
    ready = ReadyToTest()
    description.actions.append(ready)
    return ready


# --- collection: coroutines and generators are tests too, when marked ------------------------
@pytest.hookimpl(tryfirst=True)
def pytest_pycollect_makeitem(collector: Any, name: str, obj: Any) -> Any:
    if not ACTIVE or not collector.funcnamefilter(name) or not inspect.isfunction(obj):
        return None
    probe = pytest.Function.from_parent(collector, name=name)
    mark = probe.get_closest_marker(MARK)
    if mark is None:
        return None
    fixture = mark.kwargs.get("fixture")
    options = getattr(fixture, OPTIONS, None)
    if options is None:
        message = ('"fixture" keyword argument is required in a pytest.mark.launch() decorator'
                   if fixture is None else
                   f"{name}: pytest.mark.launch(fixture=…) must name a @launch_pytest.fixture, "
                   f"not {fixture!r}")
        probe.add_marker(pytest.mark.skip(reason=message))
        probe.warn(pytest.PytestWarning(message))
        return [probe]
    items = _items(collector, name, obj, fixture.__name__, shutdown=_shutdown(mark))
    if _two_parts(obj) and options["scope"] != "function":
        # its part after the yield is an item of its own, run after the launch has ended
        later = _items(collector, name, obj, fixture.__name__, shutdown=True)
        for item, after in zip(items, later, strict=True):
            item._launch_pytest_after = after
            after.name = f"{after.name}[shutdown_test]"
        items.extend(later)
    return items


def _items(collector: Any, name: str, obj: Any, fixture: str, *, shutdown: bool) -> list[Any]:
    pytest.mark.usefixtures(fixture, "launch_service", "event_loop")(obj)
    items = list(collector._genfunctions(name, obj))
    for item in items:
        item._launch_pytest_shutdown = shutdown
    return items


def _shutdown(mark: Any) -> bool:
    return bool(mark.kwargs.get("shutdown", False))


def _two_parts(function: Any) -> bool:
    return inspect.isgeneratorfunction(function) or inspect.isasyncgenfunction(function)


def _launch_fixture(item: Any) -> Any:
    mark = item.get_closest_marker(MARK)
    return None if mark is None else mark.kwargs.get("fixture")


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(session: Any, config: Any, items: list[Any]) -> None:
    """Tests that run after a shared launch has ended come after every test that runs beside
    it (the same fixture, the same parameters)."""
    if not ACTIVE:
        return
    for index in range(len(items) - 1, -1, -1):
        item = items[index]
        if not getattr(item, "_launch_pytest_shutdown", False):
            continue
        last = None
        for offset, other in enumerate(items[index + 1:]):
            if _same_launch(item, other) and not getattr(other, "_launch_pytest_shutdown",
                                                         False):
                last = index + 1 + offset
        if last is not None:
            items.insert(last, items.pop(index))


def _same_launch(left: Any, right: Any) -> bool:
    fixture = _launch_fixture(left)
    if fixture is None or fixture is not _launch_fixture(right):
        return False
    if getattr(fixture, OPTIONS)["scope"] == "function":
        return False

    def params(item: Any) -> Any:
        callspec = getattr(item, "callspec", None)
        return None if callspec is None else callspec.params.get(fixture.__name__)
    return params(left) == params(right)


# --- running a test -------------------------------------------------------------------------
@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_pyfunc_call(pyfuncitem: Any) -> Any:
    fixture = _launch_fixture(pyfuncitem) if ACTIVE else None
    if fixture is None or getattr(pyfuncitem.obj, "_launch_pytest_wrapped", False):
        return (yield)
    function = pyfuncitem.obj
    mark = pyfuncitem.get_closest_marker(MARK)
    if _shutdown(mark) and _two_parts(function):
        pytest.fail("generator or async generator based launch test items cannot be marked "
                    "with shutdown=True", pytrace=False)
    options = getattr(fixture, OPTIONS)
    loop = pyfuncitem.funcargs["event_loop"]
    launch = pyfuncitem.funcargs["launch_service"]

    def end_launch() -> None:
        launch.finish(auto_shutdown=options["auto_shutdown"])

    if _two_parts(function):
        first, rest = _split(function, loop)
        if options["scope"] == "function":
            pyfuncitem.obj = _whole(first, end_launch, rest)
        else:
            pyfuncitem.obj = first
            pyfuncitem._launch_pytest_after.obj = _after(end_launch, rest, function)
    else:
        pyfuncitem.obj = _plain(function, loop,
                                end_launch if getattr(pyfuncitem, "_launch_pytest_shutdown",
                                                      False) else None)
    return (yield)


def _plain(function: Callable[..., Any], loop: Any, before: Callable[[], None] | None) -> Any:
    """A test function or coroutine: `before` first (the launch's end, for a shutdown test)."""
    def run(**kwargs: Any) -> None:
        if before is not None:
            before()
        result = function(**kwargs)
        if inspect.iscoroutine(result):
            loop.run_until_complete(result)
    return _named(run, function)


def _split(function: Callable[..., Any], loop: Any) -> tuple[Any, Callable[[], None]]:
    """A generator test's two parts: up to its yield (given the fixtures), and the rest."""
    started: list[Any] = []

    def first(**kwargs: Any) -> None:
        generator = function(**kwargs)
        if inspect.isasyncgen(generator):
            loop.run_until_complete(generator.__anext__())
        else:
            next(generator)
        started.append(generator)  # (its rest is skipped when this part failed)

    def rest() -> None:
        if not started:
            pytest.skip("shutdown test skipped because the test failed before")
        generator = started[0]
        try:
            if inspect.isasyncgen(generator):
                loop.run_until_complete(generator.__anext__())
            else:
                next(generator)
        except (StopIteration, StopAsyncIteration):
            return
        pytest.fail("launch tests using a generator function must stop iteration after "
                    "yielding once", pytrace=False)
    return _named(first, function), rest


def _whole(first: Callable[..., None], end_launch: Callable[[], None],
           rest: Callable[[], None]) -> Any:
    def run(**kwargs: Any) -> None:
        first(**kwargs)
        end_launch()
        rest()
    return _named(run, first)


def _after(end_launch: Callable[[], None], rest: Callable[[], None],
           function: Callable[..., Any]) -> Any:
    """The item of a generator test's rest: given the same fixtures as its first part."""
    def run(**_fixtures: Any) -> None:
        end_launch()
        rest()
    return _named(run, function)


def _named(run: Callable[..., Any], function: Callable[..., Any]) -> Any:
    """`run` taking the fixtures `function` asks for (pytest reads its signature)."""
    run.__name__, run.__doc__ = function.__name__, function.__doc__
    run.__signature__ = inspect.signature(function)  # type: ignore[attr-defined]
    run._launch_pytest_wrapped = True  # type: ignore[attr-defined]
    return run
