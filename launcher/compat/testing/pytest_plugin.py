"""launch_testing's pytest plugin, as launcher's: `pytest` (and so `colcon test`) collects a
file whose `generate_test_description` is marked `@pytest.mark.launch_test` as one item, run
by `launcher test` in a process of its own (a graph of its own, everything it started gone
when it ends) and failed with the failing tests' reports. Where a real launch_testing is
installed, its own plugin collects them and this one stands aside."""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest

from launcher import compat
from launcher.compat.testing.launch_pytest.fixture import CONFIGS

MARKERS = ("launch_test", "rostest")  # launch_testing's, and launch_testing_ros's


def _real_launch_testing() -> bool:
    """A launch_testing that is not launcher's shim is importable (its plugin then runs)."""
    return compat.installed_apart("launch_testing")


def pytest_addoption(parser: Any) -> None:
    if _real_launch_testing():
        return
    parser.addoption("--launch-args", action="append", nargs="*", default=[],
                     help="launch arguments (name:=value) for the launch tests")


def pytest_configure(config: Any) -> None:
    CONFIGS.append(config)  # (launch_pytest's launch_service reads it)
    for marker in MARKERS:
        config.addinivalue_line("markers", f"{marker}: a generate_test_description function "
                                           "that is a launch test's entry point")


def pytest_unconfigure(config: Any) -> None:
    if config in CONFIGS:
        CONFIGS.remove(config)


def pytest_pycollect_makemodule(module_path: Path, parent: Any) -> Any:
    if _real_launch_testing() or not _is_launch_test(module_path):
        return None
    return LaunchTestFile.from_parent(parent, path=module_path)


def _is_launch_test(path: Path) -> bool:
    """The file defines generate_test_description marked `@pytest.mark.launch_test` (or
    launch_testing_ros's `@pytest.mark.rostest`; read, not run: nothing of the user's runs
    to find out)."""
    import ast

    try:
        tree = ast.parse(path.read_text(errors="replace"))
    except (OSError, SyntaxError, ValueError):
        return False
    return any(isinstance(node, ast.FunctionDef) and node.name == "generate_test_description"
               and any(ast.unparse(d).endswith(tuple(f"mark.{m}" for m in MARKERS))
                       for d in node.decorator_list)
               for node in tree.body)


class LaunchTestFile(pytest.File):
    def collect(self) -> Any:
        yield LaunchTestItem.from_parent(self, name=self.path.stem)


class LaunchTestFailure(Exception):
    pass


class LaunchTestItem(pytest.Item):
    def runtest(self) -> None:
        words = sum(self.config.getoption("--launch-args", default=[]) or [], [])
        with tempfile.TemporaryDirectory(prefix="launch-test-report-") as folder:
            report = Path(folder) / "report.xml"
            command = [sys.executable, "-m", "launcher", "test", str(self.path), *words,
                       "--junit-xml", str(report)]
            done = subprocess.run(command, capture_output=True, text=True,
                                  env=dict(os.environ), cwd=str(self.path.parent))
            failures = _failures(report) if report.exists() else []
        if done.returncode != 0:
            detail = "\n\n".join(failures) or done.stderr.strip() or done.stdout.strip()
            raise LaunchTestFailure(f"{self.path.name}: some launch tests failed\n\n{detail}")

    def repr_failure(self, excinfo: Any, style: Any = None) -> Any:
        if isinstance(excinfo.value, LaunchTestFailure):
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self) -> tuple[Any, int, str]:
        return self.path, 0, f"launch tests: {self.name}"


def _failures(report: Path) -> list[str]:
    """Each failed or erroring test of a JUnit report: its name and its traceback."""
    found = []
    for case in ET.parse(report).getroot().iter("testcase"):
        for outcome in (*case.findall("failure"), *case.findall("error")):
            found.append(f"FAIL: {case.get('classname')}.{case.get('name')}\n"
                         f"{outcome.text or outcome.get('message', '')}")
    return found
