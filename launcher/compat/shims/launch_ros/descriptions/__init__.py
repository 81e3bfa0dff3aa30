"""launch_ros.descriptions (launcher.api)."""

from launcher.api import ComposableNode, ParameterValue  # noqa: F401
