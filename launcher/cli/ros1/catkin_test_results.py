"""`catkin_test_results [DIR] [--verbose]`, as catkin's: the JUnit results below DIR (default
build/test_results) summed up; with --verbose, each failing test named. Exit status 1 when a
test failed or erred."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from launcher.arguments import Parser
from launcher.errors import UsageError


def main(argv: list[str], prog: str = "catkin_test_results") -> int:
    p = Parser(prog=prog, description="Summarize the results of catkin_make run_tests.")
    p.add_argument("test_results_dir", nargs="?", default="build/test_results",
                   help="the folder of results (default build/test_results)")
    p.add_argument("--verbose", action="store_true", help="show the failing tests")
    p.add_argument("--all", action="store_true", help="show every result file's counts")
    args = p.parse_args_strictly(argv)
    folder = Path(args.test_results_dir)
    if not folder.is_dir():
        raise UsageError(f"Test results directory '{folder.resolve()}' does not exist")
    totals = {"tests": 0, "errors": 0, "failures": 0, "skipped": 0}
    for report in sorted(folder.rglob("*.xml")):
        counts, failing = _read(report)
        for key in totals:
            totals[key] += counts[key]
        if args.all or (failing and args.verbose):
            print(f"{report}: {counts['tests']} tests, {counts['errors']} errors, "
                  f"{counts['failures']} failures, {counts['skipped']} skipped")
        if args.verbose:
            for name in failing:
                print(f"  {name}")
    print(f"Summary: {totals['tests']} tests, {totals['errors']} errors, "
          f"{totals['failures']} failures, {totals['skipped']} skipped")
    return 1 if totals["errors"] or totals["failures"] else 0


def _read(report: Path) -> tuple[dict[str, int], list[str]]:
    """A JUnit report's counts (its suites' attributes) and its failing test cases."""
    root = ET.parse(report).getroot()
    suites = [root] if root.tag == "testsuite" else list(root.iter("testsuite"))
    counts = {key: sum(int(s.get(key, 0) or 0) for s in suites)
              for key in ("tests", "errors", "failures", "skipped")}
    failing = [f"{case.get('classname')}.{case.get('name')}" for case in root.iter("testcase")
               if case.find("failure") is not None or case.find("error") is not None]
    return counts, failing
