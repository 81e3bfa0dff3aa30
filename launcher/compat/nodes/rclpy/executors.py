"""rclpy.executors: run the callbacks of nodes.

Every node's bus entities put their work on the node's queue and ring the context's bell; an
executor takes work from the queues of its nodes, runs due timers, and tasks (coroutines and
future callbacks). SingleThreadedExecutor runs one callback at a time on the spinning thread;
MultiThreadedExecutor hands them to a pool, one at a time per mutually exclusive group.
"""

from __future__ import annotations

import inspect
import threading
import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

from rclpy.callback_groups import is_custom
from rclpy.client import Client  # noqa: F401 - the names rclpy's module offers
from rclpy.clock import Clock, ClockType  # noqa: F401
from rclpy.context import Context  # noqa: F401
from rclpy.custody import caught_up, check_alive, live_host
from rclpy.exceptions import (  # noqa: F401
    ExternalShutdownException,
    InvalidHandle,
    TimerCancelledError,
)
from rclpy.guard_condition import GuardCondition  # noqa: F401
from rclpy.service import Service  # noqa: F401
from rclpy.signals import SignalHandlerGuardCondition  # noqa: F401
from rclpy.subscription import MessageInfo, Subscription  # noqa: F401
from rclpy.task import Future, Task
from rclpy.timer import Timer, TimerInfo, due, take  # noqa: F401
from rclpy.type_support import Msg  # noqa: F401
from rclpy.utilities import get_default_context, timeout_sec_to_nsec  # noqa: F401
from rclpy.waitable import NumberOfEntities, Waitable  # noqa: F401

BELL_LOST = 0.1  # s: the longest an executor waits without looking (see _next_work)
HELD_BACK = 0.01  # s: how soon a timer its group held back is offered again


class ShutdownException(Exception):
    """The executor was shut down."""

    def __init__(self) -> None:
        Exception.__init__(self, "Executor is shutdown")


async def await_or_execute(callback: Callable[..., Any], *args: Any) -> Any:
    """Await `callback(*args)` if it is a coroutine function, else call it."""
    if inspect.iscoroutinefunction(callback):
        return await callback(*args)
    return callback(*args)


class TimeoutException(Exception):
    """Signal that a timeout occurred."""


class TimeoutObject:
    """A timeout (seconds) kept where the code that waits can change it."""

    def __init__(self, timeout: float) -> None:
        self.timeout = timeout


class ConditionReachedException(Exception):
    """Signal that a condition was reached while spinning."""


class Executor:
    def __init__(self, *, context: Any = None) -> None:
        self._context = context or get_default_context()
        self._nodes: tuple[Any, ...] = ()  # replaced, never changed: read without the lock
        self._ready: deque[Task] = deque()
        self._lock = threading.RLock()
        self._is_shutdown = False
        self._context.on_shutdown(self.wake)

    @property
    def context(self) -> Any:
        """The context the executor runs in."""
        return self._context

    # --- nodes ------------------------------------------------------------------------------
    def add_node(self, node: Any) -> bool:
        """Spin `node` too; False if it was added already."""
        check_alive(node)
        with self._lock:
            if node in self._nodes:
                return False
            self._nodes = (*self._nodes, node)
            node.executor = self
        self.wake()  # a spin waiting now looks at the new node's work too
        return True

    def remove_node(self, node: Any) -> None:
        """Stop spinning `node`."""
        with self._lock:
            if node in self._nodes:
                self._nodes = tuple(n for n in self._nodes if n is not node)

    def get_nodes(self) -> list[Any]:
        """The nodes the executor spins."""
        with self._lock:
            return list(self._nodes)

    def wake(self) -> None:
        """Wake a spin that waits, to look at its work again."""
        self._context.ring()

    def create_task(self, callback: Any, *args: Any, **kwargs: Any) -> Task:
        """Run `callback(*args, **kwargs)` (a coroutine function may await) as a task
        of the executor: a Future of its result.
        """
        task = Task(callback, args, kwargs, executor=self)
        self.add_ready(task)
        return task

    def add_ready(self, task: Task) -> None:
        """Run `task` (new, or resumed: what it awaited is done) at the next spin."""
        self._ready.append(task)
        self.wake()

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """Stop spinning and drop the nodes; True once done."""
        self._is_shutdown = True
        with self._lock:
            for node in self._nodes:
                if getattr(node, "executor", None) is self:
                    node.executor = None
            self._nodes = ()
        self.wake()
        return True

    # --- waiting ----------------------------------------------------------------------------
    def _next_work(self, timeout_sec: float | None, lent: tuple[Any, ...] = ()
                   ) -> tuple[Any, Any, tuple] | None:
        """(node or None, callback, args) of the next ready work of the executor's nodes and
        `lent` ones, waiting up to timeout_sec (None: until some comes); None when none came."""
        deadline = None if timeout_sec is None or timeout_sec < 0 else \
            time.monotonic() + timeout_sec
        while True:
            if self._is_shutdown:
                raise ShutdownException()
            if not self._context.ok():
                raise ExternalShutdownException()
            if self._ready:
                task = self._ready.popleft()
                return None, task, ()
            nodes = self._nodes + lent if lent else self._nodes
            now = time.monotonic()
            soonest = None
            for node in nodes:  # due timers first (a flood must not starve them)
                for timer in node.timers:
                    if timer.is_canceled():
                        continue
                    until = due(timer)
                    if until == 0.0 and is_custom(timer.callback_group) and \
                            not timer.callback_group.can_execute(timer):
                        # (held back by its group, as rclpy's executor does: asked again soon)
                        until = HELD_BACK
                    elif until == 0.0:
                        return node, take(timer), ()
                    if until is not None:  # (None: on sim time, woken by the /clock)
                        soonest = now + until if soonest is None else min(soonest, now + until)
            for node in nodes:  # then waiting work
                host = live_host(node)
                work = host.next_work(0) if host is not None else None
                if work is not None:
                    return node, work[0], work[1]
            for node in nodes:  # idle: all that was due has run
                caught_up(node)
            ends = [t for t in (deadline, soonest) if t is not None]
            wait = min(ends) - now if ends else None
            if deadline is not None and now >= deadline:
                return None
            # The bell is the context's, shared by every executor of it: one may take a ring
            # meant for another (two executors on two threads, as rclpy programs have), so
            # none sleeps longer than BELL_LOST before it looks at its work again.
            if wait is None or wait > BELL_LOST:
                self._context.bell.acquire(timeout=BELL_LOST)
            elif wait > 0:
                self._context.bell.acquire(timeout=wait)

    def _run(self, node: Any, callback: Any, args: tuple) -> None:
        if isinstance(callback, Task):
            callback()
            exc = callback.exception()
            if exc is not None and callback.done():
                raise exc
            return
        result = callback(*args)
        if result is not None and hasattr(result, "send") and hasattr(result, "throw"):
            # an async callback
            task = Task(lambda: result, executor=self)
            task()

    def wait_for_ready_callbacks(self, timeout_sec: float | None = None, nodes: Any = None,
                                 condition: Any = None) -> tuple[Task, Any, Any]:
        """(handler, callback group, node) of the next ready work, as rclpy gives it to an
        executor of the user's that overrides spin_once: calling the handler (a Task) runs
        it. TimeoutException if none came within `timeout_sec`."""
        work = self._next_work(timeout_sec)
        if work is None:
            raise TimeoutException()
        node, callback, args = work
        task = Task(lambda: self._run(node, callback, args))
        group = node.default_callback_group if node is not None else None
        return task, group, node

    # --- spinning ---------------------------------------------------------------------------
    def spin_once(self, timeout_sec: float | None = None) -> None:
        """Run one ready callback (a due timer first), waiting up to `timeout_sec`
        (None: until one comes).
        """
        try:
            work = self._next_work(timeout_sec)
        except ShutdownException:  # (rclpy's spin_once lets an executor's shutdown pass)
            return
        if work is not None:
            self._run(*work)

    def spin(self) -> None:
        """Run callbacks until the context shuts down or the executor does."""
        while self._context.ok() and not self._is_shutdown:
            self.spin_once()

    def spin_once_lent(self, node: Any, timeout_sec: float | None = None) -> None:
        """`rclpy.spin_once(node)`: one turn with `node` lent for it, which is then not among
        the executor's nodes (as rclpy has it), without adding and removing it each turn."""
        if node in self._nodes:
            self.remove_node(node)
        node.executor = self
        work = self._next_work(timeout_sec, (node,))
        if work is not None:
            self._run(*work)

    def spin_until_future_complete(self, future: Future, timeout_sec: float | None = None
                                   ) -> None:
        """Run callbacks until `future` is done, or `timeout_sec` has
        passed (None or negative: no limit).
        """
        future.add_done_callback(lambda _f: self.wake())
        if timeout_sec is None or timeout_sec < 0:
            while self._context.ok() and not future.done() and not self._is_shutdown:
                self.spin_once_until_future_complete(future, None)
            return
        end = time.monotonic() + timeout_sec
        while self._context.ok() and not future.done() and not self._is_shutdown:
            left = end - time.monotonic()
            if left <= 0:
                return
            self.spin_once_until_future_complete(future, left)

    def spin_once_until_future_complete(self, future: Future,
                                        timeout_sec: float | None = None) -> None:
        """Run one callback, unless `future` is done already."""
        if future.done():
            return
        self.spin_once(timeout_sec)


class SingleThreadedExecutor(Executor):
    pass


class MultiThreadedExecutor(Executor):
    """Callbacks run on a pool of `num_threads` (default: the CPU count); a mutually
    exclusive group's callbacks one at a time, a reentrant group's in parallel."""

    def __init__(self, num_threads: int | None = None, *, context: Any = None) -> None:
        super().__init__(context=context)
        import os

        self._pool = ThreadPoolExecutor(max_workers=num_threads or os.cpu_count() or 2)
        self._errors: deque[BaseException] = deque()

    def _run(self, node: Any, callback: Any, args: tuple) -> None:
        # (each callback holds its group's lock while it runs: see Node._grouped)
        def work() -> None:
            try:
                Executor._run(self, node, callback, args)
            except BaseException as exc:  # re-raised on the spinning thread
                self._errors.append(exc)
                self.wake()
        self._pool.submit(work)

    def spin_once(self, timeout_sec: float | None = None) -> None:
        """Hand one ready callback to the thread pool, waiting up to
        `timeout_sec` for one.
        """
        if self._errors:
            raise self._errors.popleft()
        super().spin_once(timeout_sec)

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        """Stop spinning, and the pool's threads once their callbacks end."""
        super().shutdown(timeout_sec)
        self._pool.shutdown(wait=timeout_sec is None or timeout_sec > 0)
        return True
