"""launch_pytest.actions (launcher.compat.testing)."""

from launcher.compat.testing.actions import ReadyToTest

__all__ = ["ReadyToTest"]
