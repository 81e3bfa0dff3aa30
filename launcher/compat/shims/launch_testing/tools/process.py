"""launch_testing.tools.process (launcher.compat.testing)."""

from launcher.compat.testing.io_handler import ActiveIoHandler
from launcher.compat.testing.proc_info_handler import ActiveProcInfoHandler
from launcher.compat.testing.tools.process import ProcessProxy, launch_process

__all__ = ["ActiveIoHandler", "ActiveProcInfoHandler", "ProcessProxy", "launch_process"]
