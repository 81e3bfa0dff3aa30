"""launch.event_handlers (launcher.api)."""

from launcher.api import (
    OnExecutionComplete,
    OnIncludeLaunchDescription,
    OnProcessExit,
    OnProcessIO,
    OnProcessStart,
    OnShutdown,
    event_named,
)

__all__ = ["OnExecutionComplete", "OnIncludeLaunchDescription", "OnProcessExit", "OnProcessIO",
           "OnProcessStart", "OnShutdown", "event_named"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
