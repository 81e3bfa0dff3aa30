"""launch_testing.event_handlers.StdoutReadyListener: actions run once a process has printed a
text on its standard output (a process that says "ready" that way)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launcher.api import OnProcessIO


class StdoutReadyListener(OnProcessIO):
    """When `target_action`'s process (any process when None) prints `ready_txt` on stdout,
    `actions` run (each time it does)."""

    def __init__(self, *, target_action: Any = None, ready_txt: str,
                 actions: Sequence[Any]) -> None:
        self._ready_txt, self._actions = ready_txt, list(actions)
        super().__init__(target_action=target_action, on_stdout=self._on_stdout)

    def _on_stdout(self, process_io: Any, _context: Any = None) -> list[Any] | None:
        text = process_io.text
        if isinstance(text, bytes):
            text = text.decode(errors="replace")
        return self._actions if self._ready_txt in text else None

    def describe(self) -> tuple[str, list[Any]]:
        """launch's description of a handler: its text, and the actions it runs."""
        return f"StdoutReadyListener(ready_txt={self._ready_txt!r})", self._actions
