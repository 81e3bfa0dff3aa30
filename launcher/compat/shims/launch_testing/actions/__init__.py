"""launch_testing.actions (launcher.compat.testing)."""

from launcher.compat.testing.actions import GTest, PyTest, ReadyToTest

__all__ = ["GTest", "PyTest", "ReadyToTest"]
