"""launch_testing.actions.test (launcher.compat.testing)."""

from launcher.compat.testing.actions import Test

__all__ = ["Test"]
