"""launch.events: the events of a launch (launcher.runtime.events)."""

from launch.events import process
from launcher.api import matches_action
from launcher.runtime.events import (
           ExecutionComplete,
           IncludeLaunchDescription,
           Shutdown,
           TimerEvent,
)

__all__ = ["ExecutionComplete", "IncludeLaunchDescription", "Shutdown", "TimerEvent",
           "matches_action", "process"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
