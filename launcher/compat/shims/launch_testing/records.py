"""launch_testing.records (launcher.compat.testing)."""

from launcher.compat.testing.records import ProcessInfo, ProcessOutput

__all__ = ["ProcessInfo", "ProcessOutput"]
