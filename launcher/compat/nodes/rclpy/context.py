"""rclpy.context.Context: init/shutdown state, the arguments given to init, and the bell that
wakes executors (every node's bus queue rings it)."""

from __future__ import annotations

import contextlib
import threading
import weakref
from collections.abc import Callable
from typing import Any

g_logging_ref_count = 0  # how many initialized contexts configured logging


class Context:
    def __init__(self) -> None:
        self._ok = False
        self._cleaned = True  # nothing to clean up before init
        self._args: list[str] | None = None
        self._lock = threading.RLock()
        self._callbacks: list[Callable[[], None]] = []
        self._nodes: weakref.WeakSet[Any] = weakref.WeakSet()
        self.bell = threading.Lock()  # released when work comes; executors wait on it
        self.bell.acquire()
        self.domain_id = 0
        self._logging = False  # counted in g_logging_ref_count

    def init(self, args: list[str] | None = None, *, initialize_logging: bool = True,
             domain_id: int | None = None) -> None:
        """Initialize the context with the command line `args` (default sys.argv)."""
        with self._lock:
            if self._ok:
                raise RuntimeError("Context.init() must only be called once")
            self._args, self._ok, self._cleaned = args, True, False
            if initialize_logging:
                global g_logging_ref_count
                g_logging_ref_count += 1
                self._logging = True
            if domain_id is not None:
                self.domain_id = domain_id

    def ok(self) -> bool:
        """Whether the context is initialized and not shut down."""
        return self._ok

    def shutdown(self) -> None:
        """Shut the context down: its nodes are destroyed, spins end (RuntimeError if it
        is not initialized).
        """
        with self._lock:
            if self._cleaned:
                raise RuntimeError("Context must be initialized before it can be shutdown")
        self.try_shutdown()

    def try_shutdown(self) -> None:
        """Shut the context down if it is not already."""
        with self._lock:
            self._ok = False
            if self._cleaned:
                return
            self._cleaned = True
        if self._logging:
            self._logging = False
            _logging_done()
        for callback in list(self._callbacks):
            callback()
        for node in list(self._nodes):
            with contextlib.suppress(Exception):
                node.destroy_node()
        self.ring()

    def interrupt(self) -> None:
        """A signal asked to stop: not ok from now on, spinning ends; the nodes are destroyed
        by the shutdown that follows (never inside the signal handler)."""
        self._ok = False
        self.ring()

    def ring(self) -> None:
        """Wake whichever executor waits on this context's work."""
        with contextlib.suppress(RuntimeError):
            if self.bell.locked():
                self.bell.release()

    def on_shutdown(self, callback: Callable[[], None]) -> None:
        """Call `callback()` when the context shuts down."""
        self._callbacks.append(callback)

    def track_node(self, node: Any) -> None:
        """Destroy `node` when the context shuts down."""
        self._nodes.add(node)

    def get_domain_id(self) -> int:
        """The domain id given to init (0 when none was)."""
        return self.domain_id

    @property
    def args(self) -> list[str] | None:
        """The command line given to init."""
        return self._args

    def __enter__(self) -> Context:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.try_shutdown()


# The process' context: rclpy.utilities offers it (rclpy's module global); made here, below
# the modules that take it as their default (guard conditions, clocks, timers) and the signals
# module that utilities' shutdown reaches.
g_default_context = Context()


def get_default_context(*, shutting_down: bool = False) -> Context:
    """The process' context, made at first use."""
    return g_default_context


def _logging_done() -> None:
    global g_logging_ref_count
    g_logging_ref_count = max(g_logging_ref_count - 1, 0)
