"""launch_ros.event_handlers (launcher.api)."""

from launcher.api import OnStateTransition  # noqa: F401
from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
