"""A launch run in a thread of its own beside the tests (launch_pytest's `launch_service`): the
tests run in the main thread, or on their asyncio loop (`event_loop`), while the launch's own
loop supervises its processes. What the tests wait for (a process's start, output or exit) is
told to them through `LaunchWatch` (the `launch_context` they are given)."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Any

from launcher.api import (
    LaunchDescription,
    OnProcessExit,
    OnProcessIO,
    OnProcessStart,
    RegisterEventHandler,
)
from launcher.runtime.service import LaunchService

FOREVER = 365 * 24 * 3600.0  # s: the timer that keeps a launch up that must not end when idle


class LaunchWatch:
    """The processes' starts, exits and output as the tests see them: each change wakes the
    tests waiting on `until`."""

    def __init__(self, launch: ThreadedLaunch) -> None:
        self.launch = launch
        self.changed = threading.Condition()
        self._started: set[int] = set()
        self._exited: set[int] = set()

    @property
    def launch_configurations(self) -> dict[str, str]:
        return self.launch.service.context.configurations

    @property
    def environment(self) -> dict[str, str]:
        return self.launch.service.context.environment

    def has_started(self, action: Any) -> bool:
        return id(action) in self._started

    def has_exited(self, action: Any) -> bool:
        return id(action) in self._exited

    def until(self, condition: Callable[[], Any], timeout: float | None) -> Any:
        """Wait until `condition()` is true or `timeout` seconds pass; its last value."""
        deadline = None if timeout is None else time.monotonic() + timeout
        with self.changed:
            value = condition()
            while not value:
                left = None if deadline is None else deadline - time.monotonic()
                if left is not None and left <= 0:
                    break
                self.changed.wait(left)
                value = condition()
        return value

    def register_event_handler(self, event_handler: Any, append: bool = False) -> None:
        """Add `event_handler` to the running launch (first of its handlers, unless
        `append`), from the tests' thread: it is added on the launch's loop."""
        def add() -> None:
            registered = self.launch.service.handlers.registered
            registered.insert(len(registered) if append else 0, event_handler)
        self.launch.service.loop.call_soon_threadsafe(add)

    def unregister_event_handler(self, event_handler: Any) -> None:
        """Take `event_handler` out of the running launch (on its loop)."""
        def remove() -> None:
            registered = self.launch.service.handlers.registered
            if event_handler in registered:
                registered.remove(event_handler)
        self.launch.service.loop.call_soon_threadsafe(remove)

    def recorders(self) -> list[Any]:
        """Event handlers that keep the record. Output wakes the waiters once every handler
        has seen it (the action's own cache among them), on the loop's next turn."""
        def started(event: Any, _context: Any) -> None:
            self._note(self._started, event.action)

        def exited(event: Any, _context: Any) -> None:
            self._note(self._exited, event.action)

        def printed(_event: Any, _context: Any = None) -> None:  # (launch: the event alone)
            self.launch.service.loop.call_soon(self._wake)

        return [RegisterEventHandler(OnProcessStart(on_start=started)),
                RegisterEventHandler(OnProcessExit(on_exit=exited)),
                RegisterEventHandler(OnProcessIO(on_stdout=printed, on_stderr=printed))]

    def _note(self, into: set[int], action: Any) -> None:
        with self.changed:
            into.add(id(action))
            self.changed.notify_all()

    def _wake(self) -> None:
        with self.changed:
            self.changed.notify_all()


class ThreadedLaunch:
    """Launches run in a thread, one at a time, each by a new launch service (a fixture with
    parameters launches its description once for each). What launch_pytest's tests read of
    it: `event_loop` (their asyncio loop while a launch runs, None once it has ended),
    `_is_idle()`, `context`."""

    def __init__(self, new_service: Callable[[], LaunchService], event_loop: Any) -> None:
        self.new_service = new_service
        self.service: Any = None
        self.watch = LaunchWatch(self)
        self._event_loop = event_loop
        self._thread: threading.Thread | None = None
        self._ready = threading.Event()  # ReadyToTest was visited, or the launch ended first
        self._reached = False  # ReadyToTest was visited
        self.failed = False  # an action of a launch failed, or an error was reported

    # --- what tests read --------------------------------------------------------------------
    @property
    def context(self) -> LaunchWatch:
        return self.watch

    @property
    def event_loop(self) -> Any:
        return None if self.ended else self._event_loop

    @property
    def ended(self) -> bool:
        return self._thread is not None and not self._thread.is_alive()

    def _is_idle(self) -> bool:  # noqa: PLW3201 - launch's own name, read by tests
        """Nothing left to run: the launch has ended (or never began)."""
        return self._thread is None or self.ended

    # --- running ----------------------------------------------------------------------------
    def start(self, description: Any, ready: Any, *, shutdown_when_idle: bool = True) -> None:
        """Run `description` (once the launch before has ended); `ready` (its ReadyToTest)
        tells when the tests may begin."""
        self.finish(auto_shutdown=True)
        self.service, self._ready = self.new_service(), threading.Event()
        self._reached = False
        ready.add_callback(self._on_ready)
        if not shutdown_when_idle:
            self.service.add_timer(FOREVER, lambda: None)
        self.service.loop.open_posting()
        whole = LaunchDescription([*self.watch.recorders(), description])
        self._thread = threading.Thread(target=self._run, args=(whole,), daemon=True,
                                        name="launch_pytest-launch")
        self._thread.start()

    def _run(self, description: Any) -> None:
        try:
            self.service.run(description, signals=False)
        finally:
            # (a process's exit status is the tests' to judge, as in launch_pytest)
            self.failed = self.failed or self.service.ending.error
            self._ready.set()  # (a launch that ended before ReadyToTest: nothing to wait for)
            self.watch._wake()

    def _on_ready(self) -> None:
        self._reached = True
        self._ready.set()

    def wait_ready(self, timeout: float) -> bool:
        """Whether ReadyToTest was visited within `timeout` seconds (the launch may have
        ended since, its processes done: the tests judge that)."""
        return self._ready.wait(timeout) and self._reached

    def shutdown(self, reason: str = "the tests are done") -> None:
        """Ask the launch to end (nothing to do once it has)."""
        if self._thread is not None:
            self.service.loop.call_soon_threadsafe(self.service.shutdown, reason)

    def finish(self, *, auto_shutdown: bool = True) -> None:
        """Shut the launch down (unless it is to end by itself) and wait until it has."""
        if self._thread is None:
            return
        if auto_shutdown:
            self.shutdown()
        self._thread.join()  # (its processes' escalation bounds it: SIGKILL at the end)
