"""launch.actions.log (launcher's log actions): Log with its level, and one per level."""

from launcher.api import Log, LogDebug, LogError, LogInfo, LogWarning
from launcher.compat.finder import rest_from_layout
from launcher.description.actions.log import LevelFixed as SharedLogSpecificParse
from launcher.description.actions.log import Log as LogInterface

__all__ = ["Log", "LogDebug", "LogError", "LogInfo", "LogInterface", "LogWarning",
           "SharedLogSpecificParse"]
__getattr__ = rest_from_layout(__name__)
