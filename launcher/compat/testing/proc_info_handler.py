"""launch_testing's ProcInfoHandler (what the post-shutdown tests get) and
ActiveProcInfoHandler (what the active tests get: it can wait for a process)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from launcher.compat.testing.active import CONDITION, Active
from launcher.compat.testing.records import ProcessInfo
from launcher.compat.testing.util import NoMatchingProcessException, resolveProcesses


class ProcInfoHandler:
    """The last start or exit of each process, by its launch action."""

    def __init__(self) -> None:
        self._infos: dict[Any, ProcessInfo] = {}

    def append(self, info: ProcessInfo) -> None:
        self._infos[info.action] = info

    def __iter__(self) -> Iterator[ProcessInfo]:
        return iter(list(self._infos.values()))

    def processes(self) -> list[Any]:
        """The launch actions of every recorded process."""
        return list(self._infos)

    def process_names(self) -> list[str]:
        """The names of every recorded process."""
        return [info.process_name for info in self._infos.values()]

    def __getitem__(self, key: Any) -> ProcessInfo:
        """A process's record, by its launch action or (part of) its name."""
        if isinstance(key, str):
            for info in self._infos.values():
                if key in info.process_name:
                    return info
            raise KeyError(key)
        return self._infos[key]


class ActiveProcInfoHandler(Active):
    """A ProcInfoHandler that the launch fills while the active tests wait on it."""

    _record = ProcInfoHandler
    proc_event = CONDITION

    def _wait(self, process: Any, cmd_args: Any, timeout: float, exited: bool) -> bool:
        def seen() -> bool:
            try:
                action = resolveProcesses(self._handler, process=process, cmd_args=cmd_args,
                                          strict_proc_matching=True)[0]
            except NoMatchingProcessException:
                return False
            return not exited or self._handler[action].exited

        with self._changed:
            return self._changed.wait_for(seen, timeout=timeout)

    def assertWaitForShutdown(self, process: Any, cmd_args: Any = None, *,  # noqa: N802
                              timeout: float = 10) -> None:
        """Wait until `process` has exited; AssertionError after `timeout` seconds."""
        assert self._wait(process, cmd_args, timeout, exited=True), \
            f"Timed out waiting for process '{process}' to finish"

    def assertWaitForStartup(self, process: Any, cmd_args: Any = None, *,  # noqa: N802
                             timeout: float = 10) -> None:
        """Wait until `process` has started; AssertionError after `timeout` seconds."""
        assert self._wait(process, cmd_args, timeout, exited=False), \
            f"Timed out waiting for process '{process}' to start"
