"""launch_testing.test_result: unittest results that keep every test that ran and how long
each took (what junitxml writes), and the results of a run that failed or was skipped whole."""

from __future__ import annotations

import time
import unittest
from typing import Any


class FailResult(unittest.TestResult):
    """Every test of `test_run` failed with `message` (its launch died before they ran)."""

    def __init__(self, test_run: Any, message: str) -> None:
        super().__init__()
        for case in test_run.all_cases():
            self.addFailure(case, (Exception, Exception(message), None))
            self.testsRun += 1

    @property
    def testCases(self) -> list[Any]:  # noqa: N802 - launch_testing's name
        return [case for case, _ in self.failures]

    @property
    def testTimes(self) -> dict[Any, float]:  # noqa: N802
        return {case: 0 for case, _ in self.failures}

    def wasSuccessful(self) -> bool:  # noqa: N802 - unittest's name
        return False


class SkipResult(unittest.TestResult):
    """Every test of `test_run` skipped (its generate_test_description is)."""

    def __init__(self, test_run: Any, skip_reason: str = "") -> None:
        super().__init__()
        for case in test_run.all_cases():
            self.addSkip(case, skip_reason)
            self.testsRun += 1

    @property
    def testCases(self) -> list[Any]:  # noqa: N802
        return [case for case, _ in self.skipped]

    @property
    def testTimes(self) -> dict[Any, float]:  # noqa: N802
        return {case: 0 for case, _ in self.skipped}

    def wasSuccessful(self) -> bool:  # noqa: N802
        return True


class TestResult(unittest.TextTestResult):
    """unittest's text result that also records each test that ran, with its start and end."""

    def __init__(self, stream: Any = None, descriptions: Any = None,
                 verbosity: Any = None) -> None:
        self._cases: dict[Any, dict[str, float]] = {}
        super().__init__(stream, descriptions, verbosity)

    @property
    def testCases(self) -> Any:  # noqa: N802
        return self._cases.keys()

    @property
    def testTimes(self) -> dict[Any, float]:  # noqa: N802
        return {case: times["end"] - times["start"] for case, times in self._cases.items()}

    def startTest(self, test: Any) -> None:  # noqa: N802
        self._cases[test] = {"start": time.time(), "end": 0}
        super().startTest(test)

    def stopTest(self, test: Any) -> None:  # noqa: N802
        self._cases[test]["end"] = time.time()
        super().stopTest(test)

    def append(self, results: unittest.TestResult) -> None:
        """Take in `results` too (any unittest result: one that kept no times counts 0 s)."""
        cases = getattr(results, "_cases", None)
        if cases is None:
            now = time.time()
            ran = [*getattr(results, "passed", []), *(c for c, _ in results.failures),
                   *(c for c, _ in results.errors), *(c for c, _ in results.skipped)]
            cases = {case: {"start": now, "end": now} for case in ran}
        self._cases.update(cases)
        self.failures += results.failures
        self.errors += results.errors
        self.testsRun += results.testsRun
        self.skipped += results.skipped
        self.expectedFailures += results.expectedFailures
        self.unexpectedSuccesses += results.unexpectedSuccesses
