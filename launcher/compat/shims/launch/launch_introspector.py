"""launch.launch_introspector (launcher.api.introspector)."""

from launcher.api.introspector import (
    LaunchIntrospector,
    format_action,
    format_entities,
    format_event_handler,
    format_substitutions,
    indent,
    tree_like_indent,
)

__all__ = ["LaunchIntrospector", "format_action", "format_entities", "format_event_handler",
           "format_substitutions", "indent", "tree_like_indent"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
