"""launch_testing's own pytest hooks (launch_testing.pytest.hooks): a launch test file (its
generate_test_description marked `@pytest.mark.launch_test`) collected as one module of one
item, whose runs the runner class (launch_testing's LaunchTestRunner, on launcher's launch
service) runs in the pytest process. launcher's plugin (pytest_plugin.py) is the one pytest
loads; these are for plugins that build on launch_testing's."""

from __future__ import annotations

import contextlib
import copy
import pathlib
from typing import Any
from unittest import TestCase

import pytest
from _pytest._code.code import ReprFileLocation

from launcher.compat.testing import pytest_hookspecs
from launcher.compat.testing.loader import LoadTestsFromPythonModule
from launcher.compat.testing.test_runner import LaunchTestRunner


class LaunchTestFailure(Exception):
    def __init__(self, message: str, results: dict[Any, Any]) -> None:
        super().__init__()
        self.message, self.results = message, results

    def __str__(self) -> str:
        return self.message


class LaunchTestFailureRepr:
    """The failed tests of the runs, as pytest prints a failure (ExceptionReprChain-like)."""

    def __init__(self, failures: list[tuple[str, str]]) -> None:
        lines = [line for _, text in failures for line in text.splitlines()]
        width = max((len(line) for line in lines), default=3)
        self._fulldescr = "\n" + "\n\n".join(
            "\n".join(["=" * width, f"FAIL: {name}", "-" * width, text])
            for name, text in failures)
        self.reprcrash = ReprFileLocation(
            path="", lineno=0, message="\n".join(f"{name} failed" for name, _ in failures))

    def __str__(self) -> str:
        return self._fulldescr

    def toterminal(self, out: Any) -> None:
        out.write(self._fulldescr)


class LaunchTestItem(pytest.Item):
    """The runs of one launch test file, as one test."""

    def __init__(self, parent: Any, *, name: str, **kwargs: Any) -> None:
        super().__init__(name, parent, **kwargs)
        self.test_runs: Any = None
        self.runner_cls: Any = None

    @classmethod
    def from_parent(cls, parent: Any, *, name: str, test_runs: Any,  # type: ignore[override]
                    runner_cls: type = LaunchTestRunner) -> LaunchTestItem:
        item = super().from_parent(parent, name=name)
        item.test_runs, item.runner_cls = test_runs, runner_cls
        return item

    def runtest(self) -> None:
        launch_args = sum(self.config.getoption("--launch-args", default=[]) or [], [])
        runner = self.runner_cls(test_runs=copy.deepcopy(self.test_runs),  # (run again: anew)
                                 launch_file_arguments=launch_args,
                                 debug=self.config.getoption("verbose"))
        runner.validate()
        results = runner.run()
        if any(not result.wasSuccessful() for result in results.values()):
            raise LaunchTestFailure(message="some test cases have failed", results=results)

    def repr_failure(self, excinfo: Any, style: Any = None) -> Any:
        if isinstance(excinfo.value, LaunchTestFailure):
            return LaunchTestFailureRepr(failures=[
                (case.id(), text)
                for result in excinfo.value.results.values() if not result.wasSuccessful()
                for case, text in result.errors + result.failures if isinstance(case, TestCase)])
        return super().repr_failure(excinfo)

    def reportinfo(self) -> tuple[Any, int, str]:
        return self.path, 0, f"launch tests: {self.name}"


class LaunchTestModule(pytest.File):
    """A launch test file: one LaunchTestItem (`makeitem` makes it: a subclass's own)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        fspath = kwargs.pop("fspath", None)
        if fspath is not None:
            kwargs["path"] = pathlib.Path(fspath)
        super().__init__(*args, **kwargs)

    @classmethod
    def from_parent(cls, *args: Any, **kwargs: Any) -> Any:  # type: ignore[override]
        return super().from_parent(*args, **kwargs)

    def makeitem(self, *args: Any, **kwargs: Any) -> Any:
        return LaunchTestItem.from_parent(*args, **kwargs)

    def collect(self) -> Any:
        module = _import(self.path)
        yield self.makeitem(name=module.__name__, parent=self,
                            test_runs=LoadTestsFromPythonModule(module, name=module.__name__))


def _import(path: Any) -> Any:
    from _pytest.pathlib import import_path

    return import_path(pathlib.Path(path), root=None, consider_namespace_packages=False)


def find_launch_test_entrypoint(path: Any) -> Any:
    """The file's generate_test_description (None when it has none, or does not parse)."""
    try:
        return getattr(_import(path), "generate_test_description", None)
    except SyntaxError:
        return None


def pytest_pycollect_makemodule(path: Any, parent: Any) -> Any:
    entrypoint = find_launch_test_entrypoint(path)
    if entrypoint is not None:
        module = parent.session.gethookproxy(path).pytest_launch_collect_makemodule(
            path=path, parent=parent, entrypoint=entrypoint)
        if module is not None:
            return module
    path = pathlib.Path(path)
    if path.name == "__init__.py":
        return pytest.Package.from_parent(parent, path=path)
    return pytest.Module.from_parent(parent=parent, path=path)


@pytest.hookimpl(trylast=True)
def pytest_launch_collect_makemodule(path: Any, parent: Any, entrypoint: Any) -> Any:
    """A LaunchTestModule when the entry point is marked launch_test (its marks go on it)."""
    marks = getattr(entrypoint, "pytestmark", [])
    if not any(mark.name == "launch_test" for mark in marks):
        return None
    module = LaunchTestModule.from_parent(parent=parent, path=pathlib.Path(path))
    for mark in marks:
        module.add_marker(getattr(pytest.mark, mark.name).with_args(*mark.args, **mark.kwargs))
    return module


def pytest_addhooks(pluginmanager: Any) -> None:
    pluginmanager.add_hookspecs(pytest_hookspecs)


def pytest_addoption(parser: Any) -> None:
    with contextlib.suppress(ValueError):  # (launcher's own plugin has added it)
        parser.addoption("--launch-args", action="append", nargs="*", default=[],
                         help="One or more Launch test arguments")


def pytest_configure(config: Any) -> None:
    config.addinivalue_line("markers", "launch_test: mark a generate_test_description "
                                       "function as a launch test entrypoint")
