"""launch_ros.events (launcher.api)."""

from launch_ros.events import lifecycle
from launcher.api import matches_node_name

__all__ = ["lifecycle", "matches_node_name"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
