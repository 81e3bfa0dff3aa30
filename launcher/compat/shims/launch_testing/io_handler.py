"""launch_testing.io_handler (launcher.compat.testing)."""

from launcher.compat.testing.active import Active  # noqa: F401
from launcher.compat.testing.asserts import assertInStream  # noqa: F401
from launcher.compat.testing.io_handler import ActiveIoHandler, IoHandler
from launcher.compat.testing.records import ProcessOutput  # noqa: F401
from launcher.compat.testing.util import NoMatchingProcessException, resolveProcesses

__all__ = ["ActiveIoHandler", "IoHandler", "NoMatchingProcessException", "resolveProcesses"]
