"""launch_ros.parameter_descriptions (launcher.api)."""

from launcher.api import ParameterFile, ParameterValue  # noqa: F401
