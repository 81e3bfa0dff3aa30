"""launch_testing.event_handlers: StdoutReadyListener."""

from launch_testing.event_handlers.stdout_ready_listener import StdoutReadyListener

__all__ = ["StdoutReadyListener"]
