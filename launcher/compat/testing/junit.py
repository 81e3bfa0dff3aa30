"""Test results as JUnit XML (what `launcher test --junit-xml`, rostest and rostest.rosrun
write, and colcon test-result reads)."""

from __future__ import annotations

import re
import unittest
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

RESULTS_FLAG = "--gtest_output=xml:"  # where rostest asks a test to write its results


class RecordingResult(unittest.TextTestResult):
    """unittest's result, with the tests that passed kept too (a report lists every test)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.passed: list[unittest.TestCase] = []

    def addSuccess(self, test: unittest.TestCase) -> None:  # noqa: N802 - unittest's name
        super().addSuccess(test)
        self.passed.append(test)


def write(path: Path, name: str, results: list[unittest.TestResult]) -> None:
    """One <testsuite> named `name` holding every test of `results`."""
    cases: list[ET.Element] = []
    failures = errors = skipped = 0
    for result in results:
        outcomes = ([(case, "failure", text) for case, text in result.failures] +
                    [(case, "error", text) for case, text in result.errors] +
                    [(case, "skipped", text) for case, text in result.skipped])
        for case, kind, text in outcomes:
            element = _case(name, case)
            ET.SubElement(element, kind, message=_message(text) or kind).text = text
            cases.append(element)
        failures += len(result.failures)
        errors += len(result.errors)
        skipped += len(result.skipped)
        for case in getattr(result, "passed", []):
            cases.append(_case(name, case))
    total = sum(result.testsRun for result in results)
    suite = ET.Element("testsuite", name=name, tests=str(total), failures=str(failures),
                       errors=str(errors), skipped=str(skipped))
    suite.extend(cases)
    root = ET.Element("testsuites")
    root.append(suite)
    path.parent.mkdir(parents=True, exist_ok=True)
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)


def _case(suite: str, case: unittest.TestCase) -> ET.Element:
    return ET.Element("testcase", classname=f"{suite}.{type(case).__name__}",
                      name=getattr(case, "_testMethodName", str(case)))


_RAISED = re.compile(r"^[A-Za-z_][\w.]*(?:Error|Exception|Failure|Exit)\b.*$", re.M)


def _message(text: str) -> str:
    """The line that says what was raised (`AssertionError: 'a' != 'b'`), else the last."""
    found = _RAISED.findall(text or "")
    lines = (text or "").strip().splitlines()
    return found[-1] if found else (lines[-1] if lines else "")
