"""launch.events (launcher.api)."""

from launcher.api import matches_action  # noqa: F401
