"""rostest.rostest_main: the `rostest` command (launcher's, on its own graph) and what it
writes when a test file is missing."""

from __future__ import annotations

import os
import sys

from rostest.rostestutil import printRostestSummary  # noqa: F401 (rostest_main has it)

ROS_TEST_RESULTS_DIR = "ROS_TEST_RESULTS_DIR"  # the variable that says where results go


def configure_logging() -> str:
    """Log the Python logger `rostest` to a file in ROS's log folder; the file's path."""
    import logging

    home = os.environ.get("ROS_HOME") or os.path.join(os.path.expanduser("~"), ".ros")
    folder = os.environ.get("ROS_LOG_DIR") or os.path.join(home, "log")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, f"rostest-{os.uname().nodename}-{os.getpid()}.log")
    handler = logging.FileHandler(path)
    handler.setFormatter(logging.Formatter("[%(name)s][%(levelname)s] %(asctime)s: "
                                           "%(message)s"))
    logging.getLogger("rostest").addHandler(handler)
    return path


def write_bad_filename_failure(test_file: str, results_file: str, outname: str) -> None:
    """Write a JUnit result that fails because `test_file` does not exist."""
    from xml.sax.saxutils import quoteattr

    os.makedirs(os.path.dirname(results_file) or ".", exist_ok=True)
    message = quoteattr(f"rostest file [{test_file}] does not exist")
    with open(results_file, "w", encoding="utf-8") as file:
        file.write(f'<?xml version="1.0" encoding="UTF-8"?>\n'
                   f'<testsuite tests="1" failures="1" time="1" errors="0" '
                   f'name={quoteattr(outname)}>\n'
                   f'  <testcase name="test_ran" status="run" time="1" classname="Results">\n'
                   f'    <failure message={message} type=""/>\n'
                   f'  </testcase>\n</testsuite>')


def rostestmain() -> None:
    """Run the `rostest` command on sys.argv (launcher's: its graph, its reporter); exit
    with its status."""
    from launcher.cli.main import run_tool

    sys.exit(run_tool("rostest", sys.argv[1:]))
