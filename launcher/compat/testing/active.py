"""What the active tests are given while the launch runs: a record (of processes, of output)
that the launch fills from its thread and the tests read and wait on from theirs."""

from __future__ import annotations

import threading
from collections.abc import Iterator
from typing import Any


class Active:
    """The record a `_record` class makes, behind a condition the tests wait on (each kind
    names it as launch_testing does: `io_event = CONDITION`)."""

    _record: type

    def __init__(self) -> None:
        self._changed = threading.Condition()
        self._handler = self._record()

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


def _condition(active: Active) -> threading.Condition:
    return active._changed


CONDITION = property(_condition, doc="The condition the tests wait on for a change.")
