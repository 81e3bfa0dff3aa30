"""launch.event_handlers (launcher.api)."""

from launcher.api import OnProcessExit, OnProcessIO, OnProcessStart, OnShutdown  # noqa: F401
