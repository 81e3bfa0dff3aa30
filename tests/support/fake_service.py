"""Actions visited without a runtime: a service that records processes instead of starting
them (unit tests may fake the spawner), and a description run against it."""

from __future__ import annotations

from collections import deque
from typing import Any

from launcher.description.action import Action, LaunchDescription
from launcher.frontend.loader import load_file
from launcher.runtime.context import LaunchContext


class FakeService:
    """Records processes instead of starting them (unit tests may fake the spawner)."""

    def __init__(self) -> None:
        self.specs: list[Any] = []
        self.logs: list[tuple[str, str]] = []
        self.handlers: list[Any] = []
        self.launch_prefix = ""
        self.shutting_down = False
        self.coroutines = None  # (no OpaqueCoroutine runs here)
        self.count = 0
        self.later: list[Any] = []

    def next_label(self, base: str) -> str:
        self.count += 1
        return f"{base}-{self.count}"

    def start_process(self, spec: Any, started: Any = None) -> None:
        self.specs.append(spec)

    def hold_graph(self) -> None:
        pass

    def register_handler(self, handler: Any) -> None:
        self.handlers.append(handler)

    def would_handle(self, event: Any) -> bool:
        return any(handler.matches(event) for handler in self.handlers)

    def emit(self, event: Any) -> None:
        """To the handlers that match, their actions after everything queued now."""
        for handler in [h for h in self.handlers if h.matches(event)]:
            self.later.extend(handler.handle(event, self.context) or ())

    def watch_lifecycle(self, node: str, origin: Any) -> None:
        self.logs.append(("WATCH", node))

    def change_states(self, node: str, transitions: list[int], where: Any) -> None:
        self.logs.append(("CHANGE", f"{node} {transitions}"))

    def log(self, level: str, source: str, message: str) -> None:
        self.logs.append((level, message))

    def add_timer(self, period: float, callback: Any, cancel: bool = True) -> None:
        callback()  # fire at once: the clock is not what these tests are about

    def schedule(self, actions: Any) -> None:
        """After everything queued now, as the launch service queues them."""
        self.later.extend(actions)

    def shutdown(self, reason: str) -> None:
        self.logs.append(("SHUTDOWN", reason))

    def report(self, exc: Any) -> None:
        self.logs.append(("ERROR", str(exc)))


def visit(actions: list[Action], context: LaunchContext) -> None:
    """Visit depth first, as the launch service does."""
    queue = deque(actions)
    while queue:
        more = queue.popleft().visit(context)
        if more:
            queue.extendleft(reversed(list(more)))


def run(description: LaunchDescription, configurations: dict[str, str] | None = None,
        environment: dict[str, str] | None = None) -> tuple[LaunchContext, FakeService]:
    service = FakeService()
    context = LaunchContext(environment or {"PATH": "/usr/bin:/bin"}, configurations or {},
                            service=service, load_description=load_file)
    service.context = context
    visit([description], context)
    while service.later:
        actions, service.later = service.later, []
        visit(actions, context)
    return context, service
