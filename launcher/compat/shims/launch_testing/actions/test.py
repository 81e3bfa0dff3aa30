"""launch_testing.actions.Test: a process that is a test, stopped (SIGINT first) when it runs
longer than `timeout` seconds."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launcher.api import Action, ExecuteProcess, OnProcessExit
from launcher.description.substitution import perform_text, to_text


class Test(ExecuteProcess):
    """ExecuteProcess (its arguments), and `timeout`: seconds (a number or substitutions)
    before the process is stopped; none: no limit. `kill_timeout` is taken and, as in
    launch_testing, not used: the process's sigterm_timeout and sigkill_timeout escalate."""

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


__all__ = ["Test"]
