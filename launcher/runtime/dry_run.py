"""A launch visited as it would run, with nothing started: the processes it would start and
the files it read, for roslaunch's `--nodes`, `--args`, `--find-node`, `--files` and
`--dump-params`, which load the whole file as a run does (substitutions, `command=`
parameters, includes) and then print instead of running.

Timers and event handlers never fire (nothing runs for them to wait on); what a launch does
only on an event is not in the view, as with roslaunch's own, whose files have no events.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launcher.runtime.context import LaunchContext


class DryRun:
    """The Runtime actions see: it records instead of starting."""

    launch_prefix = ""
    shutting_down = False
    coroutines = None  # (nothing runs: OpaqueCoroutine looks for no loop here)

    def __init__(self) -> None:
        self.specs: list[Any] = []
        self.files: list[Path] = []
        self.warnings: list[str] = []
        self._count = 0
        self._later: list[Any] = []

    def visit(self, actions: list[Any], context: LaunchContext) -> None:
        """Visit depth first, as the launch service does, then what was scheduled after."""
        while actions:
            queue = deque(actions)
            while queue:
                more = queue.popleft().visit(context)
                if more:
                    queue.extendleft(reversed(list(more)))
            actions, self._later = self._later, []

    def loader(self, load: Callable[[Path], Any]) -> Callable[[Path], Any]:
        """`load`, noting each file it reads."""
        def noted(path: Path) -> Any:
            self.files.append(Path(path).resolve())
            return load(path)
        return noted

    def next_label(self, base: str) -> str:
        self._count += 1
        return f"{base}-{self._count}"

    def start_process(self, spec: Any, started: Any = None) -> None:
        self.specs.append(spec)

    def hold_graph(self) -> None:
        pass

    def register_handler(self, handler: Any) -> None:
        pass

    def would_handle(self, event: Any) -> bool:
        return False  # (no handler is registered: nothing happens in a dry run)

    def emit(self, event: Any) -> None:
        pass

    def watch_lifecycle(self, node: str, origin: Any) -> None:
        pass

    def change_states(self, node: str, transitions: list[int], where: Any) -> None:
        pass

    def add_timer(self, period: float, callback: Callable[[], None],
                  cancel_on_shutdown: bool = True) -> None:
        pass

    def schedule(self, actions: Any) -> None:
        self._later.extend(actions)

    def shutdown(self, reason: str) -> None:
        self.shutting_down = True

    def log(self, level: str, source: str, message: str) -> None:
        if level in ("WARN", "WARNING", "ERROR"):
            self.warnings.append(message)

    def report(self, exc: Any) -> None:
        raise exc
