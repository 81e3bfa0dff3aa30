"""launch_testing.util (launcher.compat.testing)."""

from launcher.compat.testing.util import (
    NO_CMD_ARGS,
    KeepAliveProc,
    NoMatchingProcessException,
    resolveProcesses,
)

__all__ = ["KeepAliveProc", "NO_CMD_ARGS", "NoMatchingProcessException", "resolveProcesses"]
