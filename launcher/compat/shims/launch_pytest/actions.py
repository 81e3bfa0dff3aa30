"""launch_pytest.actions: ReadyToTest (launch_testing's)."""

from launch_testing.actions import ReadyToTest

__all__ = ["ReadyToTest"]
