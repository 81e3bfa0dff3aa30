"""launch.LaunchService: a launch run by the user's own script (`ls.include_launch_description
(ld); sys.exit(ls.run())`), on the user's graph with the workspace's hooks applied, exactly as
`launcher launch` runs one."""

from __future__ import annotations

import threading
from typing import Any

FOREVER = 365 * 24 * 3600.0  # s: keeps a launch up that must not end when idle


class LaunchService:
    """Runs launch descriptions (once: a launch service is not run twice)."""

    def __init__(self, *, argv: list[str] | None = None, noninteractive: bool = False,
                 debug: bool = False) -> None:
        self.__argv = list(argv or [])
        self.__noninteractive, self.__debug = noninteractive, debug
        self.__entities: list[Any] = []
        self.__service: Any = None
        self.__running = threading.Event()
        self.__ran = False
        self.__shutdown_asked: str | None = None
        self.__async_loop: Any = None  # the asyncio loop awaiting run_async, while it does

    @property
    def context(self) -> Any:
        """The launch's context (its configurations, environment, locals)."""
        return self._service().context

    @property
    def event_loop(self) -> None:
        """None: launcher's launch runs on a selectors loop of its own, not asyncio."""
        return None

    @property
    def task(self) -> None:
        return None

    def include_launch_description(self, launch_description: Any) -> None:
        """Add a description: before the run, to what it runs; during it, at once."""
        if self.__running.is_set():
            service = self.__service
            service.loop.call_soon_threadsafe(service.schedule, [launch_description])
        else:
            self.__entities.append(launch_description)

    def emit_event(self, event: Any) -> None:
        if self.__running.is_set():
            self.__service.loop.call_soon_threadsafe(self.__service.emit, event)
        elif type(event).__name__ == "Shutdown":
            self.__shutdown_asked = getattr(event, "reason", "shutdown requested")

    def shutdown(self, force_sync: bool = False) -> Any:
        """End the launch (its processes stopped as on Ctrl-C); before it runs: at once.
        Called from within the asyncio loop that awaits `run_async`, it returns a coroutine
        that does it when awaited, as launch's does (one never awaited ends nothing)."""
        if not force_sync and self.__async_loop is not None and \
                _running_loop() is self.__async_loop:
            return self._shutdown_awaited()
        self._shutdown_now()
        return None

    async def _shutdown_awaited(self) -> None:
        self._shutdown_now()

    def _shutdown_now(self) -> None:
        if self.__running.is_set():
            self.__service.loop.call_soon_threadsafe(self.__service.shutdown,
                                                     "LaunchService.shutdown() called")
        else:
            self.__shutdown_asked = "LaunchService.shutdown() called"

    def run(self, *, shutdown_when_idle: bool = True) -> int:
        """Run until the launch ends: 0 when everything ended cleanly, 1 when an action
        failed or a process exited with a non-zero code on its own, 130 after Ctrl-C."""
        if self.__ran:  # said as launcher says a launch's errors, at the caller's line
            import sys

            caller = sys._getframe(1)
            sys.stderr.write(f"{caller.f_code.co_filename}:{caller.f_lineno}: "
                             "LaunchService.run() was called a second time: a launch service "
                             "runs once; make a new LaunchService for the next run\n")
            return 1
        self.__ran = True
        from launcher.description.action import LaunchDescription
        from launcher.description.actions.shutdown import Shutdown
        from launcher.description.substitution import to_text

        service = self._service()
        if not shutdown_when_idle:
            service.add_timer(FOREVER, lambda: None)
        entities = list(self.__entities)
        if self.__shutdown_asked is not None:
            entities.append(Shutdown(reason=to_text(self.__shutdown_asked)))
        service.loop.open_posting()
        self.__running.set()
        try:
            return service.run(LaunchDescription(entities),
                               signals=threading.current_thread() is threading.main_thread())
        finally:
            self.__running.clear()

    async def run_async(self, *, shutdown_when_idle: bool = True) -> int:
        """`run`, awaited: the launch runs in a thread of its own beside the asyncio loop."""
        import asyncio

        self.__async_loop = asyncio.get_running_loop()
        try:
            return await self.__async_loop.run_in_executor(
                None, lambda: self.run(shutdown_when_idle=shutdown_when_idle))
        finally:
            self.__async_loop = None

    def _service(self) -> Any:
        if self.__service is None:
            from launcher.cli.launch_command import launch_service
            from launcher.cli.workspace import load_index

            self.__service = launch_service({}, load_index(), debug=self.__debug,
                                            noninteractive=self.__noninteractive)
            self.__service.context.argv = self.__argv
            self.__service.context.noninteractive = self.__noninteractive
        return self.__service


def _running_loop() -> Any:
    import asyncio

    try:
        return asyncio.get_running_loop()
    except RuntimeError:
        return None


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
