"""rostest.rostestutil: rostest's log lines and its summary of a run."""

from __future__ import annotations

import sys
from typing import Any

RULE = "[ROSTEST]" + "-" * 71
_errors: list[Any] | None = None


def printlog(msg: str, *args: Any) -> None:
    """Print `msg` (filled printf-style from `args`) as rostest's, and log it."""
    import logging

    msg = msg % args if args else msg
    logging.getLogger("rostest").info(msg)
    print("[ROSTEST]" + msg)


def printlogerr(msg: str, *args: Any) -> None:
    """As printlog, on stderr, logged as an error."""
    import logging

    msg = msg % args if args else msg
    logging.getLogger("rostest").error(msg)
    print("[ROSTEST]" + msg, file=sys.stderr)


def getErrors() -> list[Any] | None:  # noqa: N802 (rostest's name)
    """The errors of the last summarised run."""
    return _errors


def printRostestSummary(result: Any, rostest_results: Any) -> None:  # noqa: N802
    """Print the summary of a run: `result` (a unittest result) and `rostest_results` (the
    test nodes' results: num_tests, num_errors and num_failures, as rosunit's)."""
    global _errors
    _errors = result.errors
    tests = getattr(rostest_results, "num_tests", 0)
    errors = len(result.errors) + getattr(rostest_results, "num_errors", 0)
    failures = len(result.failures) + getattr(rostest_results, "num_failures", 0)
    print(f"\n{RULE}\n\nSUMMARY")
    print(" * RESULT: " + ("SUCCESS" if not errors and not failures else "FAIL"))
    print(f" * TESTS: {tests}\n * ERRORS: {errors}\n * FAILURES: {failures}\n")
