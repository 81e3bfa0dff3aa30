"""launch_testing's LaunchTestRunner, which launches each run of a test file on
launcher's launch service (a graph of its own each, as `launcher test` does) with its active
tests beside it and its post-shutdown tests after it."""

from __future__ import annotations

import inspect
import unittest
from collections.abc import Sequence
from typing import Any

from launcher.api import LaunchDescription
from launcher.compat.testing.parse_arguments import parse_launch_arguments
from launcher.compat.testing.test_result import FailResult, SkipResult, TestResult
from launcher.compat.testing.worker import run_once

DIED = "Launch stopped before the active tests finished."


class LaunchTestRunner:
    """Runs `test_runs` one after the other; `launch_file_arguments` are `name:=value` words.
    `time_limit` (launcher's): seconds the active tests of a run may take (none: no limit)."""

    def __init__(self, test_runs: Sequence[Any], launch_file_arguments: Sequence[str] = (),
                 debug: bool = False, *, time_limit: float | None = None) -> None:
        self._test_runs = list(test_runs)
        self._launch_file_arguments = list(launch_file_arguments)
        self._debug, self._time_limit = debug, time_limit

    def generate_preamble(self) -> list[Any]:
        """Actions launched before each test description (none here; a subclass adds its)."""
        return []

    def run(self) -> dict[Any, unittest.TestResult]:
        """{test run: its results}; a run whose launch died before its active tests finished
        fails whole and ends the runs."""
        configurations = dict(parse_launch_arguments(self._launch_file_arguments))
        results: dict[Any, unittest.TestResult] = {}
        for run in self._test_runs:
            if len(self._test_runs) > 1:
                print(f"\nStarting test run {run}")
            try:
                results[run] = self._launch(run, configurations)
            except unittest.SkipTest as skip:
                print(f"{run} is skipped: {skip}")
                results[run] = SkipResult(test_run=run, skip_reason=str(skip))
            except _LaunchDied:
                results[run] = FailResult(test_run=run, message=DIED)
                break
        return results

    def _launch(self, run: Any, configurations: dict[str, str]) -> TestResult:
        preamble = self.generate_preamble()
        worker, parts = run_once(_Preceded(run, preamble) if preamble else run, configurations,
                                 debug=self._debug, time_limit=self._time_limit)
        if not worker.done.is_set():
            raise _LaunchDied(worker.note)
        merged = TestResult(None, True, 0)  # (the parts printed themselves)
        for part in parts:
            merged.append(part)
        return merged

    def validate(self) -> None:
        """Each run's parameters are arguments of its generate_test_description, and it takes
        no other (an Exception saying which otherwise)."""
        for run in self._test_runs:
            spec = inspect.getfullargspec(inspect.unwrap(run.function))
            taken = spec.args + spec.kwonlyargs
            for name in run.param_args:
                if name not in taken:
                    raise Exception("Could not find an argument in generate_test_description "
                                    f"matching prametrized argument '{name}'")
            for name in taken:
                if name not in run.param_args:
                    raise Exception("generate_test_description has unexpected extra argument "
                                    f"'{name}'")


class _LaunchDied(Exception):
    pass


class _Preceded:
    """A test run whose description comes after `preamble` (generate_preamble's actions)."""

    def __init__(self, run: Any, preamble: list[Any]) -> None:
        self._run, self._preamble = run, preamble

    def description(self, ready: Any) -> tuple[Any, dict[str, Any]]:
        description, context = self._run.description(ready)
        return LaunchDescription([*self._preamble, description]), context

    def __getattr__(self, name: str) -> Any:
        return getattr(self._run, name)

    def __str__(self) -> str:
        return str(self._run)
