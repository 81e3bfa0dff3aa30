"""`rostest [PKG] FILE.test [arg:=value …]`, as ROS 1's rostest: the file's nodes launched on a
graph of their own (a private run folder), then each `<test>` run once they have started, its
results read from the XML it writes (or, when it writes none, from its exit status, where
rostest gives up), and rostest's summary. Each test's results go to $ROS_TEST_RESULTS_DIR
(else $ROS_HOME/test_results, else ~/.ros/test_results), in the package's folder, as
`rosunit-TEST.xml`; the summary of them all, `rostest-FILE.xml`, goes there too, or under
`--results-base-dir`."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import Any

from launcher.arguments import Parser
from launcher.errors import LaunchError, UsageError

RULE = "[ROSTEST]" + "-" * 71


def parser(prog: str = "rostest") -> Parser:
    p = Parser(prog=prog, usage="rostest [options] [package] <filename> [arg_name:=value...]",
               description="Run a ROS 1 integration test (.test file) on launcher's graph.")
    p.add_argument("words", nargs="*", help=argparse.SUPPRESS)
    p.add_argument("-t", "--text", action="store_true",
                   help="print the tests' output (it is printed already)")
    p.add_argument("--results-filename", default=None, metavar="NAME",
                   help="the summary's file name (default rostest-FILE.xml)")
    p.add_argument("--results-base-dir", default=None, metavar="DIR",
                   help="where results go (default: $ROS_TEST_RESULTS_DIR, else "
                        "$ROS_HOME/test_results)")
    for name in ("--reuse-master", "--clear", "-r", "-c"):  # (there is no master to reuse)
        p.add_argument(name, action="store_true", help=argparse.SUPPRESS)
    return p


def main(argv: list[str], prog: str = "rostest") -> int:
    from launcher.cli.launch_command import parse_assignments
    from launcher.cli.ros1.roslaunch import resolve
    from launcher.cli.workspace import load_index
    from launcher.frontend.loader import load_file

    args = parser(prog).parse_args_strictly(argv)
    files = [w for w in args.words if ":=" not in w]
    if not files:
        raise UsageError("rostest: you must specify a test file (.test)")
    index = load_index()
    path = resolve(files, index)[0]
    configurations = parse_assignments([w for w in args.words if ":=" in w])
    description = load_file(path)
    package = files[0] if len(files) > 1 else "_hudson"  # (rostest's name when none is given)
    outcomes, not_run = _run(description, configurations, index,
                             _results_folder(None, package))
    summary = _results_folder(args.results_base_dir, package) / (
        args.results_filename or f"rostest-{path.stem}.xml")
    return _summary(outcomes, not_run, summary, path.stem)


def _results_folder(base: str | None, package: str) -> Path:
    """`base`/PKG, `base` by default $ROS_TEST_RESULTS_DIR, else $ROS_HOME/test_results (where
    each test's own results go; `--results-base-dir` moves the summary, as catkin's
    add_rostest moves it to build/test_results)."""
    base = base or os.environ.get("ROS_TEST_RESULTS_DIR") or \
        str(Path(os.environ.get("ROS_HOME", Path.home() / ".ros")) / "test_results")
    folder = Path(base) / package
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def _run(description: Any, configurations: dict[str, str], index: Any,
         results: Path) -> tuple[list[Any], list[str]]:
    """Launch the file on a graph of its own and run its tests: their outcomes, and the tests
    the launch ended before."""
    from launcher.cli.launch_command import launch_service
    from launcher.cli.own_graph import own_graph
    from launcher.cli.ros1.rostest_run import StartTests, TestsRun
    from launcher.description.action import LaunchDescription

    with own_graph("rostest-"):
        service = launch_service(configurations, index)
        run = TestsRun(service, results)
        service.context.rostests = run.collected
        service.run(LaunchDescription([description, StartTests(run)]))
    if not run.collected:
        raise LaunchError("rostest: the file has no <test>: nothing to run")
    return run.outcomes, run.not_run()


def _summary(outcomes: list[Any], not_run: list[str], report: Path, stem: str) -> int:
    """rostest's summary on stdout, the summary's XML at `report`; 0 when every test passed."""
    import xml.etree.ElementTree as ET

    print(f"\n{RULE}\n")
    for outcome in outcomes:
        print(f"[{stem}.rosunit-{outcome.name}][{'passed' if outcome.passed else 'FAILURE'}]")
        for detail in outcome.details:
            print(f"  {detail}")
    for name in not_run:
        print(f"[{stem}.rosunit-{name}][FAILURE]\n  the launch ended before it ran")
    tests = sum(o.tests for o in outcomes) + len(not_run)
    errors = sum(o.errors for o in outcomes)
    failures = sum(o.failures for o in outcomes) + len(not_run)
    ok = not errors and not failures and tests > 0
    print(f"\nSUMMARY\n * RESULT: {'SUCCESS' if ok else 'FAIL'}\n * TESTS: {tests}\n"
          f" * ERRORS: {errors}\n * FAILURES: {failures}\n")
    suite = ET.Element("testsuite", name=f"rostest-{stem}", tests=str(tests),
                       errors=str(errors), failures=str(failures))
    for outcome in outcomes:
        case = ET.SubElement(suite, "testcase", classname=f"{stem}.rosunit",
                             name=outcome.name)
        if not outcome.passed:
            ET.SubElement(case, "failure", message="; ".join(outcome.details) or "failed")
    ET.ElementTree(suite).write(report, encoding="utf-8", xml_declaration=True)
    print(f"rostest results are in {report}", file=sys.stderr)
    return 0 if ok else 1
