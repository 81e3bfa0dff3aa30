"""launch_ros.event_handlers (launcher.api)."""

from launcher.api import OnStateTransition  # noqa: F401
