"""launch_ros.events.lifecycle (launcher.api)."""

from launcher.api import ChangeState  # noqa: F401
