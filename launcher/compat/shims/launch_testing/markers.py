"""launch_testing.markers (launcher.compat.testing)."""

from launcher.compat.testing.markers import keep_alive, retry_on_failure

__all__ = ["keep_alive", "retry_on_failure"]
