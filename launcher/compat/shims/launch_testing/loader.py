"""launch_testing.loader (launcher.compat.testing)."""

from launcher.compat.testing.actions import ReadyToTest
from launcher.compat.testing.loader import (
    READY_TIMEOUT,
    LoadTestsFromPythonModule,
    PostShutdownTestLoader,
    PreShutdownTestLoader,
    TestFileError,
    TestRun,
    bind,
    load_runs,
    ready_actions,  # noqa: F401
    slim_formatwarning,
)

__all__ = [
    "READY_TIMEOUT", "LoadTestsFromPythonModule", "PostShutdownTestLoader",
    "PreShutdownTestLoader", "ReadyToTest", "TestFileError", "TestRun", "bind", "load_runs",
    "slim_formatwarning"
]
