"""launch_testing.launch_test (launcher.compat.testing): `python -m launch_testing.launch_test
FILE …` is `launcher test`."""

from launcher.compat.testing.junitxml import unittestResultsToXml
from launcher.compat.testing.launch_test import add_arguments, main, parse_arguments, run
from launcher.compat.testing.loader import LoadTestsFromPythonModule
from launcher.compat.testing.print_arguments import print_arguments_of_launch_description
from launcher.compat.testing.test_runner import LaunchTestRunner

__all__ = [
    "LaunchTestRunner", "LoadTestsFromPythonModule", "add_arguments", "main",
    "parse_arguments", "print_arguments_of_launch_description", "run", "unittestResultsToXml"
]


if __name__ == "__main__":
    main()
