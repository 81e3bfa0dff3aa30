"""launch_testing.legacy (launcher.compat.testing)."""

from launch_testing.legacy import output
from launcher.compat.testing.legacy import LaunchTestService

__all__ = ["LaunchTestService", "output"]
