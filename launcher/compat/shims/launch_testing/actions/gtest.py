"""launch_testing.actions.gtest (launcher.compat.testing)."""

from launcher.compat.testing.actions import GTest, Test

__all__ = ["GTest", "Test"]
