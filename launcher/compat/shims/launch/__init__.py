"""ROS 2's `launch` package, answered by launcher.api (see launcher.compat)."""

from launch import actions, conditions, event_handlers, launch_description_sources, substitutions
from launcher.api import Action, LaunchDescription, Substitution
from launcher.runtime.context import LaunchContext

SomeSubstitutionsType = object
__all__ = ["Action", "LaunchContext", "LaunchDescription", "Substitution", "SomeSubstitutionsType",
           "actions", "conditions", "event_handlers", "launch_description_sources",
           "substitutions"]
