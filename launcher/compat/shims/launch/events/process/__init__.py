"""launch.events.process: the events of a launch's processes, and matchers of the process
actions that ShutdownProcess and SignalProcess are for."""

from collections.abc import Callable
from typing import Any

from launcher.runtime.events import (
    ProcessExited,
    ProcessIO,
    ProcessStarted,
    ProcessStderr,
    ProcessStdin,
    ProcessStdout,
    ProcessTargetedEvent,
    RunningProcessEvent,
    ShutdownProcess,
    SignalProcess,
)


def _details(action: Any) -> Any:
    return getattr(action, "process_details", None)


def matches_pid(pid: int) -> Callable[[Any], bool]:
    """The process action whose process has this pid."""
    return lambda action: _details(action) is not None and _details(action)["pid"] == pid


def matches_name(name: str) -> Callable[[Any], bool]:
    """The process action whose process has this name (its label: `talker-1`)."""
    return lambda action: _details(action) is not None and _details(action)["name"] == name


def matches_executable(executable: str) -> Callable[[Any], bool]:
    """The process actions whose command's first word ends with `executable`."""
    return lambda action: _details(action) is not None and \
        str(_details(action)["cmd"][0]).endswith(executable)


__all__ = ["ProcessExited", "ProcessIO", "ProcessStarted", "ProcessStderr", "ProcessStdin",
           "ProcessStdout", "ProcessTargetedEvent", "RunningProcessEvent", "ShutdownProcess",
           "SignalProcess", "matches_executable", "matches_name", "matches_pid"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
