"""ROS 2's `launch_ros` package, answered by launcher.api (see launcher.compat)."""

from launch_ros import (
    actions,
    descriptions,
    event_handlers,
    events,
    parameter_descriptions,
    parameters_type,
    substitutions,
    utilities,
)

__all__ = ["actions", "descriptions", "event_handlers", "events", "parameter_descriptions",
           "parameters_type", "substitutions", "utilities"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
