"""launch_testing's launch_test: `python -m launch_testing.launch_test FILE …` is launcher's
`launch_test` (`launcher test`), run with this interpreter; `run` is launch_testing's own
entry, for tools that drive it with a runner class of theirs."""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
from pathlib import Path

from launcher.compat.testing.junitxml import unittestResultsToXml
from launcher.compat.testing.loader import LoadTestsFromPythonModule
from launcher.compat.testing.print_arguments import print_arguments_of_launch_description
from launcher.compat.testing.test_runner import LaunchTestRunner


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """launch_test's arguments."""
    parser.add_argument("launch_test_file", help="Path to the launch test.")
    parser.add_argument("--package-name", action="store", default=None,
                        help="Name of the package the test is in. Useful to aggregate xUnit "
                             "reports.")
    parser.add_argument("-v", "--verbose", action="store_true", default=False,
                        help="Run with verbose output")
    parser.add_argument("-s", "--show-args", "--show-arguments", action="store_true",
                        default=False, help="Show arguments that may be given to the launch "
                                            "test.")
    parser.add_argument("launch_arguments", nargs="*",
                        help="Arguments in '<name>:=<value>' format (for duplicates, last one "
                             "wins).")
    parser.add_argument("--junit-xml", action="store", dest="xmlpath", default=None,
                        help="Do write xUnit reports to specified path.")


def parse_arguments() -> tuple[argparse.ArgumentParser, argparse.Namespace]:
    parser = argparse.ArgumentParser(description="Launch integration testing tool.")
    add_arguments(parser)
    return parser, parser.parse_args()


def run(parser: argparse.ArgumentParser, args: argparse.Namespace,
        test_runner_cls: type = LaunchTestRunner) -> int | None:
    """Run the test file `args` names with `test_runner_cls`: 0 when every test passed, 1
    otherwise (None after --show-args)."""
    if not os.path.isfile(args.launch_test_file):
        parser.error(f"Test file '{args.launch_test_file}' does not exist")  # (it exits)
    args.launch_test_file = os.path.abspath(args.launch_test_file)
    stem = os.path.splitext(os.path.basename(args.launch_test_file))[0]
    args.package_name = args.package_name or stem
    spec = importlib.util.spec_from_file_location(args.package_name, args.launch_test_file)
    module = importlib.util.module_from_spec(spec)  # type: ignore[arg-type]
    spec.loader.exec_module(module)  # type: ignore[union-attr]
    test_runs = LoadTestsFromPythonModule(module,
                                          name=f"{args.package_name}.{stem}.launch_tests")
    runner = test_runner_cls(test_runs=test_runs, launch_file_arguments=args.launch_arguments,
                             debug=args.verbose)
    runner.validate()
    if args.show_args:
        description = test_runs[0].get_launch_description()
        description.file = Path(args.launch_test_file)
        print_arguments_of_launch_description(launch_description=description)
        return None
    results = runner.run()
    if args.xmlpath:
        report = unittestResultsToXml(test_results=results, name=f"{args.package_name}.{stem}")
        report.write(args.xmlpath, encoding="utf-8", xml_declaration=True)
    return 0 if all(result.wasSuccessful() for result in results.values()) else 1


def main() -> None:
    os.execv(sys.executable, [sys.executable, "-m", "launcher", "test", *sys.argv[1:]])

