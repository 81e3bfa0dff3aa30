"""launch_testing.proc_info_handler (launcher.compat.testing)."""

from launcher.compat.testing.active import Active  # noqa: F401
from launcher.compat.testing.proc_info_handler import ActiveProcInfoHandler, ProcInfoHandler
from launcher.compat.testing.records import ProcessInfo  # noqa: F401
from launcher.compat.testing.util import NoMatchingProcessException, resolveProcesses  # noqa: F401

__all__ = ["ActiveProcInfoHandler", "ProcInfoHandler"]
