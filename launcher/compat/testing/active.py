"""What the active tests are given while the launch runs: a record (of processes, of output)
that the launch fills from its thread and the tests read and wait on from theirs."""

from __future__ import annotations

import threading
from collections.abc import Iterator
from typing import Any


class Active:
    """The record `handler`, behind a condition the tests wait on."""

    def __init__(self, handler: Any) -> None:
        self._changed = threading.Condition()
        self._handler = handler

    def append(self, item: Any) -> None:
        with self._changed:
            self._handler.append(item)
            self._changed.notify_all()

    def __iter__(self) -> Iterator[Any]:
        with self._changed:
            return iter(self._handler)

    def processes(self) -> list[Any]:
        """The launch actions of every recorded process."""
        with self._changed:
            return self._handler.processes()

    def process_names(self) -> list[str]:
        """The names of every recorded process."""
        with self._changed:
            return self._handler.process_names()

    def __getitem__(self, key: Any) -> Any:
        with self._changed:
            return self._handler[key]

    def snapshot(self) -> Any:
        """The record itself, for the post-shutdown tests."""
        return self._handler
