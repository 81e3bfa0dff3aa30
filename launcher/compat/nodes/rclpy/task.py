"""rclpy.task: Future (awaitable, with done callbacks) and Task (a coroutine run by an
executor, resumed when the future it awaits is done)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from enum import Enum
from typing import Any


class FutureState(Enum):
    """Where a Future stands."""

    PENDING = "PENDING"
    CANCELLED = "CANCELLED"
    FINISHED = "FINISHED"


_driving = threading.local()  # .task: an executor's Task is stepping a coroutine here


class Future:
    def __init__(self, *, executor: Any = None) -> None:
        self._state = FutureState.PENDING
        self._result: Any = None
        self._exception: BaseException | None = None
        self._callbacks: list[Callable[[Future], None]] = []
        self._lock = threading.Lock()
        self._executor = executor
        self._waiting: list[threading.Event] = []

    def __await__(self) -> Any:
        while self._state == FutureState.PENDING:
            # To an executor's Task, the future itself (it resumes the task when this is
            # done); to anything else (asyncio), a bare yield, as rclpy's Future gives
            yield self if getattr(_driving, "task", False) else None
        return self.result()

    def cancel(self) -> None:
        """Cancel the future: it is done, and has no result."""
        self._finish(FutureState.CANCELLED)

    def cancelled(self) -> bool:
        """Whether the future was canceled."""
        return self._state == FutureState.CANCELLED

    def done(self) -> bool:
        """Whether the future has a result, an exception, or was canceled."""
        return self._state != FutureState.PENDING

    def result(self) -> Any:
        """The result (None until done); the exception, raised, if it failed."""
        if self._exception is not None:
            raise self._exception
        return self._result

    def exception(self) -> BaseException | None:
        """The exception the future failed with, or None."""
        return self._exception

    def set_result(self, result: Any) -> None:
        """Complete the future with `result`; its done callbacks run."""
        self._result = result
        self._finish(FutureState.FINISHED)

    def set_exception(self, exception: BaseException) -> None:
        """Complete the future with an exception; its done callbacks run."""
        self._exception = exception
        self._finish(FutureState.FINISHED)

    def _finish(self, state: FutureState) -> None:
        with self._lock:
            if self._state != FutureState.PENDING:
                return
            self._state = state
            callbacks, self._callbacks = self._callbacks, []
            waiting, self._waiting = self._waiting, []
        for event in waiting:  # a blocking wait wakes now, not a turn of the executor later
            event.set()
        for callback in callbacks:
            self._schedule(callback)

    def _schedule(self, callback: Callable[[Future], None]) -> None:
        executor = self._executor
        if executor is not None:
            executor.create_task(callback, self)
        else:
            callback(self)

    def _wake_on_done(self, event: threading.Event) -> None:
        """Set `event` the moment this is done (for a thread that blocks on it)."""
        with self._lock:
            if self._state == FutureState.PENDING:
                self._waiting.append(event)
                return
        event.set()

    def add_done_callback(self, callback: Callable[[Future], None]) -> None:
        """Call `callback(future)` when it is done (on its executor, if it
        has one; at once if it is done already).
        """
        with self._lock:
            if self._state == FutureState.PENDING:
                self._callbacks.append(callback)
                return
        self._schedule(callback)

    def remove_done_callback(self, callback: Callable[[Future], None]) -> bool:
        """Remove a done callback; False if it was not there."""
        with self._lock:
            if callback in self._callbacks:
                self._callbacks.remove(callback)
                return True
        return False

    def _set_executor(self, executor: Any) -> None:
        self._executor = executor


class Task(Future):
    """A callback or coroutine run by the executor; a coroutine resumes when what it awaits
    is done."""

    def __init__(self, handler: Any, args: tuple = (), kwargs: dict | None = None,
                 executor: Any = None) -> None:
        super().__init__(executor=executor)
        self._handler, self._args, self._kwargs = handler, args, kwargs or {}
        self._coroutine: Any = None
        self._running = threading.Lock()

    def __call__(self) -> None:
        if self.done() or not self._running.acquire(blocking=False):
            return
        try:
            if self._coroutine is None:
                result = self._handler(*self._args, **self._kwargs)
                if hasattr(result, "send") and hasattr(result, "throw"):
                    self._coroutine = result
                else:
                    self.set_result(result)
                    return
            self._step()
        finally:
            self._running.release()

    def _step(self) -> None:
        outer, _driving.task = getattr(_driving, "task", False), True
        try:
            awaited = self._coroutine.send(None)
        except StopIteration as end:
            self.set_result(end.value)
            return
        except Exception as exc:  # the task's error: kept on the task, re-raised by the executor
            self.set_exception(exc)
            raise
        finally:
            _driving.task = outer
        if isinstance(awaited, Future):
            awaited.add_done_callback(lambda _f: self._resume())
        else:
            self._resume()

    def _resume(self) -> None:
        if self._executor is not None:
            self._executor.add_ready(self)
        else:
            self()

    def executing(self) -> bool:
        """Whether the task's coroutine is running now."""
        return self._running.locked()


def wake_on_done(future: Future, event: threading.Event) -> None:
    """Set `event` when the future is done (a blocking wait on another thread)."""
    future._wake_on_done(event)


def has_executor(future: Future) -> bool:
    """Whether an executor runs the future's done callbacks."""
    return future._executor is not None
