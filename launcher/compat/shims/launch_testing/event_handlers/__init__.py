"""launch_testing.event_handlers (launcher.compat.testing)."""

from launcher.compat.testing.event_handlers import StdoutReadyListener

__all__ = ["StdoutReadyListener"]
