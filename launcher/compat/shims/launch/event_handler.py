"""launch.event_handler (launcher.api)."""

from launcher.api import BaseEventHandler, EventHandler

__all__ = ["BaseEventHandler", "EventHandler"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
