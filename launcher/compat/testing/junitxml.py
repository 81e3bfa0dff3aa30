"""launch_testing.junitxml: test results as a JUnit XML document (launch_test --junit-xml).
Times come from launch_testing's TestResult (FailResult and SkipResult count 0 s)."""

from __future__ import annotations

import unittest
import xml.etree.ElementTree as ET
from typing import Any


def unittestResultsToXml(*, name: str = "launch_test",  # noqa: N802 - launch_testing's name
                         test_results: dict[Any, Any] | None = None) -> ET.ElementTree:
    """A <testsuites> of one <testsuite> per entry of `test_results` ({run: result})."""
    results = test_results or {}
    suites = ET.Element("testsuites", name=name)
    suites.set("tests", str(sum(r.testsRun for r in results.values())))
    suites.set("failures", str(sum(len(r.failures) for r in results.values())))
    suites.set("errors", str(sum(len(r.errors) for r in results.values())))
    suites.set("time", str(round(sum(sum(r.testTimes.values()) for r in results.values()), 3)))
    for run, result in results.items():
        suites.append(unittestResultToXml(str(run), result))
    return ET.ElementTree(suites)


def unittestResultToXml(name: str, test_result: Any) -> ET.Element:  # noqa: N802
    """<testsuite name tests failures errors skipped time> with a <testcase> per test."""
    suite = ET.Element("testsuite", name=name, tests=str(test_result.testsRun),
                       failures=str(len(test_result.failures)),
                       errors=str(len(test_result.errors)),
                       skipped=str(len(test_result.skipped)),
                       time=str(round(sum(test_result.testTimes.values()), 3)))
    for case in test_result.testCases:
        suite.append(unittestCaseToXml(test_result, case))
    return suite


def unittestCaseToXml(test_result: Any, test_case: unittest.TestCase) -> ET.Element:  # noqa: N802
    """<testcase classname name time>, with its <failure>, <error> or <skipped>."""
    method, _, qualifiers = test_case.id().partition(" ")
    classname, _, methodname = method.rpartition(".")
    case = ET.Element("testcase", classname=classname,
                      name=f"{methodname} {qualifiers}".strip(),
                      time=str(round(test_result.testTimes[test_case], 3)))
    for tag, outcomes in (("failure", test_result.failures), ("error", test_result.errors),
                          ("skipped", test_result.skipped)):
        for failed, text in outcomes:
            if failed == test_case:
                ET.SubElement(case, tag, message=text)
    return case
