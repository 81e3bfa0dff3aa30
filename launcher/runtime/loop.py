"""A small single-threaded event loop over `selectors`: file readers and writers, timers and
signals.

The launcher uses this rather than asyncio because importing asyncio alone takes ~75 ms on
the reference machine, most of the 0.10 s budget for having ten processes running; this
loop does what supervision needs (readers, monotonic timers, signals through a wakeup fd) in
about a hundred lines. Signal handlers only hand the signal to the loop, except inside
`interruptible()`: there the signal raises `Interrupted` at once, so that a long evaluation or
a `$(command)` being waited for does not hold up Ctrl-C (the loop then does not see that
signal a second time). A signal raised as `Interrupted` is counted until the code that acts on
it says it `took` it; one that something else swallowed is handed to the loop's handler at the
loop's next turn. A handled signal is counted by the handler itself; the wakeup fd only
wakes the loop (its bytes can be dropped when it is full: a storm of SIGCHLD must not cost a
SIGTERM), and signals that came together are handled together (SIGCHLD once).
"""

from __future__ import annotations

import contextlib
import heapq
import itertools
import os
import selectors
import signal
import threading
import time
from collections import Counter, deque
from collections.abc import Callable, Iterator
from typing import Any

from launcher.errors import Interrupted


class Timer:
    __slots__ = ("when", "callback", "args", "cancelled")

    def __init__(self, when: float, callback: Callable[..., Any], args: tuple) -> None:
        self.when, self.callback, self.args, self.cancelled = when, callback, args, False

    def cancel(self) -> None:
        self.cancelled = True


TRACE = os.environ.get("LAUNCHER_SIGNAL_TRACE", "")  # a file each signal seen is added to


def trace(what: str) -> None:
    """A line in the LAUNCHER_SIGNAL_TRACE file: when, and what the loop saw or did (for
    bench/signals.py: a lost signal's last steps)."""
    fd = os.open(TRACE, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o600)
    try:
        os.write(fd, f"{time.time():.6f} {os.getpid()} {what}\n".encode())
    finally:
        os.close(fd)


class EventLoop:
    def __init__(self, clock: Callable[[], float] = time.monotonic) -> None:
        self.time = clock
        self._selector = selectors.DefaultSelector()
        self._watched = self._selector.get_map()  # (a live view: fd → key)
        self._timers: list[tuple[float, int, Timer]] = []
        self._sequence = itertools.count()
        self._signals: dict[int, Callable[[int], None]] = {}
        self._previous: dict[int, Any] = {}
        self._wakeup: tuple[int, int] | None = None
        self._busy = 0  # depth of interruptible() sections
        self._pending: Counter[int] = Counter()  # signals for the loop's handlers
        self._raised: Counter[int] = Counter()  # raised as Interrupted, not yet taken
        self._stopped = False
        self._posted: deque[tuple[Callable[..., Any], tuple]] = deque()  # from other threads
        self._post_pipe: tuple[int, int] | None = None
        self._post_lock = threading.Lock()
        self._closed = False

    # --- scheduling -----------------------------------------------------------------------
    def call_soon(self, callback: Callable[..., Any], *args: Any) -> Timer:
        return self.call_later(0.0, callback, *args)

    def call_later(self, delay: float, callback: Callable[..., Any], *args: Any) -> Timer:
        timer = Timer(self.time() + max(delay, 0.0), callback, args)
        heapq.heappush(self._timers, (timer.when, next(self._sequence), timer))
        return timer

    def call_soon_threadsafe(self, callback: Callable[..., Any], *args: Any) -> bool:
        """`callback(*args)` on the loop's thread, from any thread (a worker's result); False
        when the loop has been closed (nothing runs it any more)."""
        with self._post_lock:  # (not while close() closes the pipe: its fd could be reused)
            if self._closed:
                return False
            if self._post_pipe is None:
                raise RuntimeError("call open_posting() on the loop's thread first")
            self._posted.append((callback, args))
            with contextlib.suppress(BlockingIOError, OSError):
                os.write(self._post_pipe[1], b"\0")
        return True

    def open_posting(self) -> None:
        """Make call_soon_threadsafe ready (a pipe the loop reads); idempotent."""
        if self._post_pipe is None:
            read, write = os.pipe()
            os.set_blocking(read, False)
            os.set_blocking(write, False)
            self._post_pipe = (read, write)
            self.add_reader(read, self._on_posted)

    def _on_posted(self) -> None:
        with contextlib.suppress(BlockingIOError):
            os.read(self._post_pipe[0], 4096)  # type: ignore[index]
        while self._posted:
            callback, args = self._posted.popleft()
            callback(*args)

    def add_reader(self, fd: int, callback: Callable[..., Any], *args: Any) -> None:
        self._watch(fd, selectors.EVENT_READ, (callback, args))

    def remove_reader(self, fd: int) -> None:
        self._watch(fd, selectors.EVENT_READ, None)

    def add_writer(self, fd: int, callback: Callable[..., Any], *args: Any) -> None:
        """`callback(*args)` whenever `fd` can take more (a non-blocking writer's queue)."""
        self._watch(fd, selectors.EVENT_WRITE, (callback, args))

    def remove_writer(self, fd: int) -> None:
        self._watch(fd, selectors.EVENT_WRITE, None)

    def _watch(self, fd: int, event: int, handler: tuple | None) -> None:
        """Set (or, with None, drop) the handler of one event of `fd`; an fd may have a
        reader and a writer, each an entry of its key's {event: handler}."""
        try:
            handlers = dict(self._selector.get_key(fd).data)
        except (KeyError, ValueError):  # (ValueError: a closed fd, or not one)
            handlers = {}
        if handler is None:
            handlers.pop(event, None)
        else:
            handlers[event] = handler
        mask = 0
        for each in handlers:
            mask |= each
        with contextlib.suppress(KeyError, ValueError):
            self._selector.unregister(fd)
        if mask:
            self._selector.register(fd, mask, handlers)

    # --- signals --------------------------------------------------------------------------
    def add_signal_handler(self, sig: int, callback: Callable[[int], None]
                           ) -> list[tuple[int, str]]:
        """`callback(sig)` on the loop for each `sig` received from now on. Returns the
        signals the handler it replaces raised that nothing acted on ((signum, where it was
        raised): the handler's `take_raised()`, as cli/entry.py's has, which gives them all,
        whichever signal is being taken over); they are received again, at the loop's first
        turn, by the handlers added by then: add every signal's before it runs."""
        if self._wakeup is None:
            read, write = os.pipe()
            os.set_blocking(read, False)
            os.set_blocking(write, False)
            self._wakeup = (read, write)
            signal.set_wakeup_fd(write, warn_on_full_buffer=False)
            self.add_reader(read, self._on_signals)
        self._signals[sig] = callback
        previous = signal.signal(sig, self._on_signal)  # the wakeup fd carries it to the loop
        self._previous.setdefault(sig, previous)
        take = getattr(previous, "take_raised", None)
        unacted = take() if callable(take) else []
        for signum, _ in unacted:
            self._pending[signum] += 1
            with contextlib.suppress(OSError):
                os.write(self._wakeup[1], b"\0")
        return unacted

    def remove_signal_handlers(self) -> None:
        for sig in self._signals:
            previous = self._previous.get(sig)
            signal.signal(sig, previous if previous is not None else signal.SIG_DFL)
        self._signals.clear()
        self._previous.clear()
        if self._wakeup is not None:
            signal.set_wakeup_fd(-1)
            self.remove_reader(self._wakeup[0])
            for fd in self._wakeup:
                os.close(fd)
            self._wakeup = None

    @contextlib.contextmanager
    def interruptible(self) -> Iterator[None]:
        """A section that a signal handed to the loop interrupts with `Interrupted`."""
        self._busy += 1
        try:
            yield
        finally:
            self._busy -= 1

    @contextlib.contextmanager
    def shielded(self) -> Iterator[None]:
        """A section a signal must not cut in two (a process being spawned and recorded): the
        signal waits for the loop, as outside `interruptible()`."""
        busy, self._busy = self._busy, 0
        try:
            yield
        finally:
            self._busy = busy

    def _on_signal(self, signum: int, _frame: Any) -> None:
        if TRACE:
            trace(f"loop {signum} busy={self._busy}")
        if self._busy and signum in (signal.SIGINT, signal.SIGTERM):
            self._raised[signum] += 1  # (until taken: code that swallows it loses nothing)
            raise Interrupted(signum)
        self._pending[signum] += 1
        if self._wakeup is not None:  # (the interpreter's byte may have been read already)
            with contextlib.suppress(OSError):
                os.write(self._wakeup[1], b"\0")

    def _on_signals(self) -> None:
        with contextlib.suppress(BlockingIOError):
            os.read(self._wakeup[0], 4096)  # type: ignore[index]  # (they only wake the loop)
        pending, self._pending = self._pending, Counter()
        if TRACE and pending:
            trace(f"handled {dict(pending)}")
        for number, count in pending.items():
            handler = self._signals.get(number)
            if handler is None:
                continue
            for _ in range(count if number in (signal.SIGINT, signal.SIGTERM) else 1):
                handler(number)

    def took(self, signum: int) -> None:
        """An Interrupted raised for `signum` reached the code that acts on it."""
        if self._raised[signum] > 0:
            self._raised[signum] -= 1

    def _recover(self) -> None:
        """Signals raised as Interrupted that nothing took (a library's `except
        BaseException`, a __del__) are handed to their handlers as if just received."""
        raised, self._raised = self._raised, Counter()
        self._pending.update(+raised)
        self._on_signals()

    # --- running --------------------------------------------------------------------------
    def stop(self) -> None:
        self._stopped = True

    def run(self) -> None:
        """Run until `stop()`."""
        self._stopped = False
        while not self._stopped:
            self._run_once()

    def _run_once(self) -> None:
        if self._raised and not self._busy:
            self._recover()
            if self._stopped:
                return
        timeout = None
        if self._timers:
            timeout = max(0.0, self._timers[0][0] - self.time())
        for key, ready in self._selector.select(timeout):
            for event in (selectors.EVENT_READ, selectors.EVENT_WRITE):
                # (looked up again: the reader's callback may have dropped the writer)
                handler = key.data.get(event) if ready & event else None
                if handler is not None and self._watched.get(key.fd) is key:
                    handler[0](*handler[1])
                    if self._stopped:
                        return
        now = self.time()
        while self._timers and self._timers[0][0] <= now and not self._stopped:
            _, _, timer = heapq.heappop(self._timers)
            if not timer.cancelled:
                timer.callback(*timer.args)

    def close(self) -> None:
        self.remove_signal_handlers()
        with self._post_lock:
            self._closed = True
            if self._post_pipe is not None:
                self.remove_reader(self._post_pipe[0])
                for fd in self._post_pipe:
                    os.close(fd)
                self._post_pipe = None
        self._selector.close()
