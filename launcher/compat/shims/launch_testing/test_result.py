"""launch_testing.test_result (launcher.compat.testing)."""

from launcher.compat.testing.test_result import FailResult, SkipResult, TestResult

__all__ = ["FailResult", "SkipResult", "TestResult"]
