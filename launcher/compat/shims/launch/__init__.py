"""ROS 2's `launch` package, answered by launcher.api (see launcher.compat)."""

from typing import Any

from launch import (
    actions,
    conditions,
    event_handlers,
    events,
    launch_description_sources,
    substitutions,
    utilities,
)
from launch.launch_service import LaunchService
from launcher.api import (
    Action,
    Condition,
    EventHandler,
    LaunchDescription,
    LaunchDescriptionEntity,
    LaunchDescriptionSource,
    SomeEntitiesType,
    SomeEntitiesType_types_tuple,
    SomeSubstitutionsType,
    SomeSubstitutionsType_types_tuple,
    Substitution,
)
from launcher.api.introspector import LaunchIntrospector
from launcher.api.sources import InvalidLaunchFileError
from launcher.runtime.context import LaunchContext
from launcher.runtime.events import Event

__all__ = [
    "Action", "Condition", "Event", "EventHandler", "InvalidLaunchFileError", "LaunchContext",
    "LaunchDescription", "LaunchDescriptionEntity", "LaunchDescriptionSource",
    "LaunchIntrospector", "LaunchService", "SomeEntitiesType", "SomeEntitiesType_types_tuple",
    "SomeSubstitutionsType", "SomeSubstitutionsType_types_tuple", "Substitution", "actions",
    "conditions", "event_handlers", "events", "launch_description_sources", "logging",
    "substitutions", "utilities",
]


from launcher.compat.finder import rest_from_layout  # noqa: E402

_rest = rest_from_layout(__name__)


def __getattr__(name: str) -> Any:
    """launch.logging, imported when first asked for (Python's logging costs a launch's
    start-up some 10 ms, and most launch files never touch it); the real package's other
    names as the layout finds them."""
    if name == "logging":
        import launch.logging

        return launch.logging
    return _rest(name)
