"""A launch test file read as launch_testing reads it: its `generate_test_description` (one
run, or one per parametrization), its active tests and its post-shutdown tests, and the
arguments each test method, setUp and tearDown is given by name."""

from __future__ import annotations

import functools
import inspect
import os
import unittest
from collections.abc import Callable, Iterator
from typing import Any

from launcher.compat.testing.actions import ReadyToTest

READY_TIMEOUT = 15.0  # s ReadyToTest is waited for, unless ready_to_test_action_timeout says


class TestRun:
    """One launch of a test file and the tests that run with and after it."""

    def __init__(self, name: str, test_description_function: Callable[..., Any],
                 param_args: dict[str, Any], pre_shutdown_tests: unittest.TestSuite,
                 post_shutdown_tests: unittest.TestSuite) -> None:
        self.name, self.param_args = name, param_args
        self._test_description_function = self.function = test_description_function
        self.pre_shutdown_tests, self.post_shutdown_tests = pre_shutdown_tests, \
            post_shutdown_tests
        self.timeout = float(getattr(test_description_function,
                                     "__ready_to_test_action_timeout__", READY_TIMEOUT))
        if param_args:
            for case in self.cases():
                method = getattr(case, case._testMethodName)
                renamed = case._testMethodName + self.params_text()
                setattr(case, renamed, method)
                case._testMethodName = renamed
        for suite in (*_suites(pre_shutdown_tests), *_suites(post_shutdown_tests)):
            suite._removeTestAtIndex = lambda *args, **kwargs: None  # keep them to bind again

    # (launcher's worker reads the suites by these names)
    active = property(lambda self: self.pre_shutdown_tests)
    post_shutdown = property(lambda self: self.post_shutdown_tests)

    @property
    def markers(self) -> dict[str, Any]:
        """keep_alive and the like, as launch_testing.markers set them."""
        return getattr(self.function, "__markers__", None) or {}

    def normalized_test_description(self, ready_fn: Callable[[], None]
                                    ) -> tuple[Any, dict[str, Any]]:
        """launch_testing's name of `description`."""
        return self.description(ready_fn)

    def get_launch_description(self) -> Any:
        """The launch description alone, to look at (not to launch)."""
        return self.description(lambda: None)[0]

    def bind(self, tests: unittest.TestSuite, injected_attributes: dict[str, Any] | None = None,
             injected_args: dict[str, Any] | None = None) -> None:
        """Give `tests` the attributes (self.name) and the arguments (by name) given."""
        for cls in {type(case) for case in _tests(tests)}:
            for name, value in (injected_attributes or {}).items():
                setattr(cls, name, value)
        bind(tests, dict(injected_args or {}))

    def all_cases(self) -> Iterator[unittest.TestCase]:
        return self.cases()

    def description(self, ready: Callable[[], None]) -> tuple[Any, dict[str, Any]]:
        """The launch description and the test context it returns, its ReadyToTest told to
        call `ready`."""
        try:
            result = self.function()
        except Exception as exc:  # the test file's own code failed: said at its line
            raise TestFileError(_raised_at(self.function, exc)) from None
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
        yield from _tests(self.pre_shutdown_tests)
        yield from _tests(self.post_shutdown_tests)

    def params_text(self) -> str:
        return f"[{', '.join(map(str, self.param_args.values()))}]" if self.param_args else ""

    def __str__(self) -> str:
        return self.name + self.params_text()


def _raised_at(function: Callable[..., Any], exc: BaseException) -> str:
    """`file:line: generate_test_description raised …`, at the innermost line of the test
    file's own code."""
    import traceback

    code = getattr(function, "__code__", None) or getattr(
        getattr(function, "func", None), "__code__", None)
    frames = traceback.extract_tb(exc.__traceback__)
    mine = [f for f in frames if code is not None and f.filename == code.co_filename]
    place = f"{mine[-1].filename}:{mine[-1].lineno}: " if mine else \
        (f"{code.co_filename}:{code.co_firstlineno}: " if code else "")
    return f"{place}generate_test_description raised {type(exc).__name__}: {exc}"


class TestFileError(Exception):
    """A test file launch_testing cannot run (said as a failed test, with the reason)."""


def load_runs(module: Any, name: str) -> list[TestRun]:
    """The runs of a test module (several when its description is parametrized)."""
    if getattr(module, "generate_test_description", None) is None:
        raise TestFileError(f"{getattr(module, '__file__', name)}: a launch test file must "
                            "define generate_test_description()")
    return LoadTestsFromPythonModule(module, name=name)


def LoadTestsFromPythonModule(module: Any, *, name: str = "launch_tests"  # noqa: N802
                              ) -> list[TestRun]:
    """launch_testing's name: a TestRun for each launch of `module`'s description."""
    function = module.generate_test_description
    variants = list(function()) if getattr(function, "__parametrized__", False) \
        else [(function, {})]
    return [TestRun(name, variant, args, PreShutdownTestLoader().loadTestsFromModule(module),
                    PostShutdownTestLoader().loadTestsFromModule(module))
            for variant, args in variants]


def PreShutdownTestLoader() -> unittest.TestLoader:  # noqa: N802 - launch_testing's name
    """A loader of the test classes that run while the launch runs."""
    return _loader(False)


def PostShutdownTestLoader() -> unittest.TestLoader:  # noqa: N802
    """A loader of the test classes marked @post_shutdown_test."""
    return _loader(True)


def slim_formatwarning(msg: Any, *args: Any, **kwargs: Any) -> str:
    """A warning as one line, `Warning: …` (launch_testing's warnings.formatwarning)."""
    return f"Warning: {msg}{os.linesep}"


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
