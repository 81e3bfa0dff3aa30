"""launch_testing.test_runner (launcher.compat.testing)."""

from launcher.compat.testing.io_handler import ActiveIoHandler
from launcher.compat.testing.parse_arguments import parse_launch_arguments
from launcher.compat.testing.proc_info_handler import ActiveProcInfoHandler
from launcher.compat.testing.test_result import FailResult, SkipResult, TestResult
from launcher.compat.testing.test_runner import LaunchTestRunner

__all__ = [
    "ActiveIoHandler", "ActiveProcInfoHandler", "FailResult", "LaunchTestRunner", "SkipResult",
    "TestResult", "parse_launch_arguments"
]
