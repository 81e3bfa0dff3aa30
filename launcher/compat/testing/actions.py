"""launch_testing's actions: ReadyToTest, the action that says the tests may start, and the
actions that run a test program (Test; GTest, PyTest)."""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from typing import Any

from launcher.api import Action, ExecuteProcess, OnProcessExit
from launcher.description.substitution import perform_text, to_text


class ReadyToTest(Action):
    """Visited, it tells the test runner that the processes before it have started and the
    active tests may begin."""

    def __init__(self, **kwargs: Any) -> None:
        self.condition, self.where = kwargs.get("condition"), kwargs.get("where")
        self.callbacks: list[Callable[[], None]] = []

    def add_callback(self, callback: Callable[[], None]) -> None:
        self.callbacks.append(callback)

    _add_callback = add_callback  # (launch_testing's own name, which its tools call)

    def execute(self, context: Any) -> Sequence[Action] | None:
        for callback in self.callbacks:
            callback()
        return None


class Test(ExecuteProcess):
    """ExecuteProcess (its arguments), and `timeout`: seconds (a number or substitutions)
    before the process is stopped (SIGINT first); none: no limit. `kill_timeout` is taken
    and, as in launch_testing, not used: the process's sigterm_timeout and sigkill_timeout
    escalate."""

    def __init__(self, *, timeout: Any = None, kill_timeout: Any = 5.0, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._timeout, self._kill_timeout = timeout, kill_timeout

    @property
    def timeout(self) -> Any:
        return self._timeout

    def execute(self, context: Any) -> Sequence[Action] | None:
        actions = super().execute(context)
        service = context.service
        if not self._timeout or not hasattr(service, "table"):  # (none in a dry run)
            return actions
        seconds = float(self._timeout) if isinstance(self._timeout, int | float) else \
            float(perform_text(context, to_text(self._timeout)))
        timer = service.add_timer(seconds, lambda: service.table.stop_started_by(self))

        def exited(_event: Any, _context: Any) -> None:
            service.timers.live.pop(timer, None)  # (a live timer would keep the launch up)
            timer.cancel()

        service.register_handler(OnProcessExit(target_action=self, on_exit=exited))
        return actions


class GTest(Test):
    """A GoogleTest program: runs the program at `path` (Test's and ExecuteProcess's other
    arguments)."""

    def __init__(self, *, path: Any, **kwargs: Any) -> None:
        super().__init__(cmd=[path], **kwargs)
        self._path = path

    @property
    def path(self) -> Any:
        return self._path


class PyTest(Test):
    """`python -m pytest PATH`, with this interpreter (Test's and ExecuteProcess's other
    arguments)."""

    def __init__(self, *, path: Any, **kwargs: Any) -> None:
        super().__init__(cmd=[sys.executable, "-m", "pytest", path], **kwargs)
        self._path = path

    @property
    def path(self) -> Any:
        return self._path
