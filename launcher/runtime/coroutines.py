"""The launch's asyncio loop (launch's `context.asyncio_loop`): OpaqueCoroutine's coroutines,
and tasks the user's code puts there, run on it, on a thread of its own beside launcher's
loop. It starts when first asked for. The launch waits for the coroutines it started, as
launch does, and cancels them when it shuts down."""

from __future__ import annotations

import threading
from collections.abc import Callable, Coroutine
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # (concurrent.futures costs the launch's start-up 5 ms)
    from concurrent.futures import Future

JOIN = 5.0  # s: the most the launch's end waits for the loop's thread


class Coroutines:
    def __init__(self, post: Callable[[Callable[[], None]], None],
                 on_error: Callable[[BaseException], None], on_done: Callable[[], None]) -> None:
        """`post(callback)` runs callback on launcher's loop (from any thread); `on_error`
        hears a coroutine's failure and `on_done` each end, there."""
        self._post, self._on_error, self._on_done = post, on_error, on_done
        self._loop: Any = None  # (asyncio is imported when first asked for: start-up time)
        self._thread: threading.Thread | None = None
        self._running: set[Future] = set()
        self._lock = threading.Lock()

    @property
    def asyncio_loop(self) -> Any:
        with self._lock:
            if self._loop is None:
                import asyncio

                self._loop = asyncio.new_event_loop()
                self._thread = threading.Thread(target=self._loop.run_forever, daemon=True,
                                                name="launch-asyncio")
                self._thread.start()
            return self._loop

    @property
    def out(self) -> int:
        """How many started coroutines have not ended."""
        return len(self._running)

    def run(self, coroutine: Coroutine[Any, Any, Any]) -> None:
        """Run `coroutine` on the loop; the launch waits for its end."""
        import asyncio

        future = asyncio.run_coroutine_threadsafe(coroutine, self.asyncio_loop)
        self._running.add(future)
        future.add_done_callback(lambda done: self._post(lambda: self._ended(done)))

    def _ended(self, future: Future) -> None:
        self._running.discard(future)
        if not future.cancelled() and future.exception() is not None:
            self._on_error(future.exception())
        self._on_done()

    def cancel(self) -> None:
        """The launch is shutting down: its coroutines are cancelled."""
        for future in list(self._running):
            future.cancel()

    def close(self) -> None:
        """The launch is over: the loop stops and its thread ends."""
        with self._lock:
            loop, thread, self._loop = self._loop, self._thread, None
        if loop is None or thread is None:
            return
        loop.call_soon_threadsafe(loop.stop)
        thread.join(JOIN)
        if not thread.is_alive():
            loop.close()
