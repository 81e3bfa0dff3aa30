"""A launch test file read as launch_testing reads it: its `generate_test_description` (one
run, or one per parametrization), its active tests and its post-shutdown tests, and the
arguments each test method, setUp and tearDown is given by name."""

from __future__ import annotations

import functools
import inspect
import unittest
from collections.abc import Callable, Iterator
from typing import Any

from launch_testing.actions import ReadyToTest

READY_TIMEOUT = 15.0  # s ReadyToTest is waited for, unless ready_to_test_action_timeout says


class TestRun:
    """One launch of a test file and the tests that run with and after it."""

    def __init__(self, name: str, description_function: Callable[..., Any],
                 param_args: dict[str, Any], active: unittest.TestSuite,
                 post_shutdown: unittest.TestSuite) -> None:
        self.name, self.function, self.param_args = name, description_function, param_args
        self.active, self.post_shutdown = active, post_shutdown
        self.timeout = float(getattr(description_function,
                                     "__ready_to_test_action_timeout__", READY_TIMEOUT))
        self.markers: dict[str, Any] = getattr(description_function, "__markers__", None) or {}
        if param_args:
            for case in self.cases():
                method = getattr(case, case._testMethodName)
                renamed = case._testMethodName + self.params_text()
                setattr(case, renamed, method)
                case._testMethodName = renamed
        for suite in (*_suites(active), *_suites(post_shutdown)):
            suite._removeTestAtIndex = lambda *args, **kwargs: None  # keep them to bind again

    def description(self, ready: Callable[[], None]) -> tuple[Any, dict[str, Any]]:
        """The launch description and the test context it returns, its ReadyToTest told to
        call `ready`."""
        result = self.function()
        description, context = result if isinstance(result, tuple) else (result, {})
        found = list(ready_actions(getattr(description, "actions", [])))
        if not found:
            code = getattr(self.function, "__code__", None) or getattr(
                getattr(self.function, "func", None), "__code__", None)
            where = f"{code.co_filename}:{code.co_firstlineno}: " if code else ""
            raise TestFileError(f"{where}generate_test_description functions must return a "
                                "LaunchDescription containing a ReadyToTest action")
        for action in found:
            action.add_callback(ready)
        return description, dict(context)

    def cases(self) -> Iterator[unittest.TestCase]:
        yield from _tests(self.active)
        yield from _tests(self.post_shutdown)

    def params_text(self) -> str:
        return f"[{', '.join(map(str, self.param_args.values()))}]" if self.param_args else ""

    def __str__(self) -> str:
        return self.name + self.params_text()


class TestFileError(Exception):
    """A test file launch_testing cannot run (said as a failed test, with the reason)."""


def load_runs(module: Any, name: str) -> list[TestRun]:
    """The runs of a test module (several when its description is parametrized)."""
    function = getattr(module, "generate_test_description", None)
    if function is None:
        raise TestFileError(f"{getattr(module, '__file__', name)}: a launch test file must "
                            "define generate_test_description()")
    if getattr(function, "__parametrized__", False):
        variants = list(function())
    else:
        variants = [(function, {})]
    return [TestRun(name, variant, args, _loader(False).loadTestsFromModule(module),
                    _loader(True).loadTestsFromModule(module)) for variant, args in variants]


def bind(tests: unittest.TestSuite, values: dict[str, Any]) -> None:
    """Give each test method, setUp, tearDown and the classes' setUpClass/tearDownClass the
    values they take by name (proc_info, proc_output, the test context, …); the objects are
    also the classes' attributes, as launch_testing gives them (self.proc_info)."""
    classes = []
    for case in _tests(tests):
        for attribute in (case._testMethodName, "setUp", "tearDown"):
            setattr(case, attribute, _given(getattr(case, attribute), values))
        if type(case) not in classes:
            classes.append(type(case))
    for cls in classes:
        for name in ("proc_info", "proc_output", "test_args", "launch_service"):
            if name in values:
                setattr(cls, name, values[name])
        for attribute in ("setUpClass", "tearDownClass"):
            setattr(cls, attribute, _given(getattr(cls, attribute), values))


def _given(function: Callable[..., Any], values: dict[str, Any]) -> Callable[..., Any]:
    taken = inspect.signature(function).parameters
    return functools.partial(function, **{k: v for k, v in values.items() if k in taken})


def _loader(post_shutdown: bool) -> unittest.TestLoader:
    class Loader(unittest.TestLoader):
        def loadTestsFromTestCase(self, case_class: type) -> unittest.TestSuite:  # noqa: N802
            if getattr(case_class, "__post_shutdown_test__", False) != post_shutdown:
                return self.suiteClass()
            # a class of its own per run: binding one run's values never touches another's
            own = type(case_class.__name__, (case_class,), {"__module__": case_class.__module__})
            return super().loadTestsFromTestCase(own)

    return Loader()


def ready_actions(actions: Any) -> Iterator[ReadyToTest]:
    for action in actions:
        if isinstance(action, ReadyToTest):
            yield action
        sub = getattr(action, "sub_actions", None)
        if sub is not None:
            yield from ready_actions(sub())


def _suites(suite: Any) -> Iterator[unittest.TestSuite]:
    if isinstance(suite, unittest.TestSuite):
        yield suite
        for child in suite:
            yield from _suites(child)


def _tests(suite: Any) -> Iterator[unittest.TestCase]:
    if isinstance(suite, unittest.TestSuite):
        for child in suite:
            yield from _tests(child)
    else:
        yield suite


__all__ = ["READY_TIMEOUT", "TestFileError", "TestRun", "bind", "load_runs"]
