"""An event loop for unit tests: timers on a clock the test moves, readers the test makes
ready (runtime/loop.py's EventLoop, without the operating system)."""

from __future__ import annotations

import contextlib
import heapq
import itertools

from launcher.runtime.loop import Timer


class FakeLoop:
    def __init__(self) -> None:
        self.now = 0.0
        self._timers: list = []
        self._order = itertools.count()
        self.readers: dict[int, tuple] = {}

    def time(self) -> float:
        return self.now

    def call_later(self, delay, callback, *args):
        when = self.now + max(delay, 0.0)
        timer = Timer(when, callback, args)
        heapq.heappush(self._timers, (when, next(self._order), timer, callback, args))
        return timer

    def add_reader(self, fd, callback, *args):
        self.readers[fd] = (callback, args)

    def remove_reader(self, fd):
        self.readers.pop(fd, None)

    def add_writer(self, fd, callback, *args):
        pass  # (a test flushes what is written itself)

    def remove_writer(self, fd):
        pass

    def close(self):
        pass

    @contextlib.contextmanager
    def shielded(self):
        yield

    def advance(self, seconds: float) -> None:
        end = self.now + seconds
        while self._timers and self._timers[0][0] <= end:
            when, _, timer, callback, args = heapq.heappop(self._timers)
            self.now = when
            if not timer.cancelled:
                callback(*args)
        self.now = end

    def ready(self, fd: int) -> None:
        callback, args = self.readers[fd]
        callback(*args)
