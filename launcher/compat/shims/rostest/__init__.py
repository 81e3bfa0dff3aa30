"""rostest's Python side over launcher: `rostest.rosrun(package, test_name, TestCase)`, what a
ROS 1 test node calls to run its unittest cases and write the results where rostest reads
them (`--gtest_output=xml:PATH` on its command line). A real rostest that the user installed
wins."""

from __future__ import annotations

import sys
import unittest
from pathlib import Path
from typing import Any

from launcher.compat.junit import RESULTS_FLAG, RecordingResult, write


def results_file(argv: list[str]) -> Path | None:
    """Where rostest asked for the results (`--gtest_output=xml:PATH`), if it did."""
    for word in argv:
        if word.startswith(RESULTS_FLAG):
            return Path(word[len(RESULTS_FLAG):])
    return None


def rosrun(package: str, test_name: str, test: Any, sysargs: list[str] | None = None) -> None:
    """Run `test` (a TestCase class, or a suite), write its results for rostest, and exit
    with 0 when every case passed, else 1."""
    argv = sys.argv if sysargs is None else sysargs
    suite = unittest.TestLoader().loadTestsFromTestCase(test) if isinstance(test, type) \
        else test
    result = unittest.TextTestRunner(verbosity=2, resultclass=RecordingResult).run(suite)
    target = results_file(argv)
    if target is not None:
        write(target, f"{package}.{test_name}", [result])
    sys.exit(0 if result.wasSuccessful() else 1)


def unitrun(package: str, test_name: str, test: Any, sysargs: list[str] | None = None,
            coverage_packages: Any = None) -> None:
    """rosunit's unitrun: the same, for a test run without a launch."""
    rosrun(package, test_name, test, sysargs)


__all__ = ["rosrun", "unitrun"]
