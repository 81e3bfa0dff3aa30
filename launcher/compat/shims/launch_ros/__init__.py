"""ROS 2's `launch_ros` package, answered by launcher.api (see launcher.compat)."""

from launch_ros import actions, parameter_descriptions, substitutions  # noqa: F401
