"""ROS 2's `launch_ros` package, answered by launcher.api (see launcher.compat)."""

from launch_ros import (  # noqa: F401
    actions,
    descriptions,
    parameter_descriptions,
    substitutions,
)
