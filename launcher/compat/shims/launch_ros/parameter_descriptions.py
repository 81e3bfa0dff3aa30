"""launch_ros.parameter_descriptions (launcher.api)."""

from launcher.api import ParameterValue  # noqa: F401
