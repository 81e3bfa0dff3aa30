"""`launcher test FILE [name:=value …]`: a launch test, as `launch_test` runs it (the shell's
`launch_test` and `ros2 test` are this command). Each run of the file is launched on a graph of
its own (a private run folder: no ROS_DOMAIN_ID to pick), and everything it started is gone
when it ends. Exit status 0 when every test passed, 1 otherwise."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from launcher.cli import positive_number
from launcher.errors import LaunchError, UsageError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Run a launch test (launch_testing's generate_test_description, active and "
        "post-shutdown tests). Exit status: 0 when every test passed, 1 otherwise.")
    parser.add_argument("launch_test_file", metavar="FILE", help="the launch test")
    parser.add_argument("launch_arguments", nargs="*", metavar="name:=value",
                        help="launch arguments (the last of the same name wins)")
    parser.add_argument("--package-name", default=None,
                        help="the package the test is in (names its results)")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="debug messages, and tracebacks with errors")
    parser.add_argument("-s", "--show-args", "--show-arguments", action="store_true",
                        help="list the launch arguments the test takes, and exit")
    parser.add_argument("--junit-xml", dest="xmlpath", default=None, metavar="PATH",
                        help="also write the results as JUnit XML here")
    parser.add_argument("--timeout", type=positive_number, default=None, metavar="SECONDS",
                        help="fail the run when its active tests take longer than this "
                             "(default: no limit, as launch_test)")


def run(args: argparse.Namespace) -> int:
    from launcher import compat
    from launcher.cli.launch_command import parse_assignments
    from launcher.cli.workspace import load_index
    from launcher.compat.testing.junit import write
    from launcher.compat.testing.loader import TestFileError, load_runs
    from launcher.compat.testing.worker import run_once
    from launcher.frontend.python_loader import load_module

    path = Path(args.launch_test_file)
    if not path.is_file():
        raise UsageError(f"Test file '{path}' does not exist")
    path = path.resolve()
    configurations = parse_assignments(args.launch_arguments)
    compat.enable_in_process()  # test files import launch, launch_testing, rclpy, …
    name = args.package_name or path.stem
    module = load_module(path, name, "test file")
    try:
        runs = load_runs(module, f"{name}.{path.stem}.launch_tests")
        if args.show_args:
            from launcher.cli import views

            description = runs[0].description(lambda: None)[0]
            description.file = path
            print(views.show_arguments(description, configurations, load_index()), end="")
            return 0
    except TestFileError as exc:
        raise LaunchError(str(exc)) from None
    results = []
    for test_run in runs:
        if len(runs) > 1:
            print(f"\nStarting test run {test_run}", file=sys.stderr)
        try:
            _worker, found = run_once(test_run, configurations, debug=args.verbose,
                                      time_limit=args.timeout)
            results += found
        except TestFileError as exc:
            raise LaunchError(str(exc)) from None
    if args.xmlpath:
        write(Path(args.xmlpath), f"{name}.{path.stem}", results)
    return 0 if all(result.wasSuccessful() for result in results) else 1


