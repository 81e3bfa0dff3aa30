"""launch_testing.actions.pytest (launcher.compat.testing)."""

from launcher.compat.testing.actions import PyTest, Test

__all__ = ["PyTest", "Test"]
