"""Processes that wait before they start, as roslaunch has them wait: while a helper puts the
launch's ROS 1 parameters on the graph, every process that may join the graph waits until it
says it is done (a helper that ends before that fails the launch, and they never start); a
process `after_loading` also waits until the actions queued with it are visited (the launch
files read). What waited starts once nothing holds it."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.errors import ExecutionError, LaunchError
from launcher.runtime.process import ProcessSpec

Started = Callable[[Any], None] | None


class StartGate:
    def __init__(self, start: Callable[[ProcessSpec, Started], None],
                 fail: Callable[[LaunchError], None], report: Callable[[LaunchError], None],
                 shutting_down: Callable[[], bool], reading: Callable[[], bool]) -> None:
        """`start` spawns a process (OSError when it cannot); `reading` says whether the
        launch's actions are being visited now."""
        self._start, self._fail, self._report = start, fail, report
        self._shutting_down, self._reading = shutting_down, reading
        self._holds = 0  # helpers to come or at work that graph processes wait for
        self._held: list[tuple[ProcessSpec, Started]] = []

    @property
    def waiting(self) -> bool:
        """Whether processes wait to start (and the launch is not ending)."""
        return bool(self._held) and not self._shutting_down()

    def keeps(self, spec: ProcessSpec, started: Started) -> bool:
        """Whether `spec` must wait (it is kept, to start later)."""
        if (self._holds and spec.joins_graph and not spec.helper_done_line) or \
                (spec.after_loading and self._reading()):
            self._held.append((spec, started))
            return True
        return False

    def hold(self) -> None:
        """A helper is coming that puts the launch's parameters on the graph."""
        self._holds += 1

    def helper_over(self, done: bool) -> None:
        """A helper has ended: `done` if it said its work was done."""
        self._holds = max(0, self._holds - 1)
        if self._shutting_down():
            self._held.clear()
            return
        if not done:
            self._held.clear()
            self._fail(ExecutionError("the launch's parameters could not be set on the "
                                      "parameter server (the error is above); no node was "
                                      "started"))
            return
        self.release()

    def release(self) -> None:
        """Start what waited, once nothing holds it."""
        if self._holds or self._reading():
            return
        held, self._held = self._held, []
        for spec, started in held:
            if self._shutting_down():
                return
            where = getattr(spec.origin, "where", None)
            try:
                self._start(spec, started)
            except LaunchError as exc:  # (another host that cannot be reached)
                self._fail(exc.at(where))
                return
            except OSError as exc:
                self._report(ExecutionError(f"cannot start '{spec.program}': "
                                            f"{exc.strerror or exc}", where))
