"""launch.actions.shutdown_action (launcher.api)."""

from launcher.api import Shutdown
from launcher.compat.finder import rest_from_layout
from launcher.runtime.events import Shutdown as ShutdownEvent

__all__ = ["Shutdown", "ShutdownEvent"]
__getattr__ = rest_from_layout(__name__)
