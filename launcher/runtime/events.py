"""Events the runtime emits, and the handler protocol that event-handler actions implement."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple, Protocol


class ProcessStarted(NamedTuple):
    origin: Any  # the action that started the process
    label: str
    pid: int
    argv: tuple[str, ...] = ()  # its command line, substitutions done
    cwd: str | None = None


class ProcessExited(NamedTuple):
    origin: Any
    label: str
    pid: int | None
    returncode: int | None


class ProcessIO(NamedTuple):
    origin: Any
    label: str
    stream: str  # stdout | stderr
    text: str


class Shutdown(NamedTuple):
    reason: str


Event = ProcessStarted | ProcessExited | ProcessIO | Shutdown


class EventHandler(Protocol):
    def matches(self, event: Event) -> bool: ...

    def handle(self, event: Event, context: Any) -> Sequence[Any] | None: ...
