"""A batch's progress on stderr: a bar redrawn in place on a terminal, a line per job and a
summary every 30 s elsewhere (a CI log), and a line for every job that did not pass."""

from __future__ import annotations

import shutil
import time
from collections.abc import Callable
from typing import TextIO

from launcher import records
from launcher.batch.matrix import JobPlan
from launcher.batch.results import JobResult, Status

BAR = 20  # the bar's widest
NARROWEST_BAR = 5  # below this the bar is left out
CLEAR = "\r\x1b[K"  # back to the line's start, and clear it
LOG_EVERY = 30.0  # seconds between summary lines when not on a terminal


@records.dataclass
class ProgressState:
    total: int
    passed: int = 0
    failed: int = 0
    errors: int = 0
    timeouts: int = 0
    cancelled: int = 0
    running: int = 0
    elapsed: float = 0.0

    @property
    def done(self) -> int:
        return self.passed + self.failed + self.errors + self.timeouts + self.cancelled

    @property
    def queued(self) -> int:
        return max(0, self.total - self.done - self.running)

    @property
    def left_s(self) -> float | None:
        """Remaining × elapsed / done: jobs so far are the best guess of jobs to come."""
        if not self.done:
            return None
        return (self.total - self.done) * self.elapsed / self.done


def span(seconds: float) -> str:
    """`3.2s`, `42s`, `1m05s`, `2h03m`."""
    if seconds < 10:
        return f"{seconds:.1f}s"
    whole = round(seconds)
    if whole < 60:
        return f"{whole}s"
    if whole < 3600:
        return f"{whole // 60}m{whole % 60:02d}s"
    return f"{whole // 3600}h{whole // 60 % 60:02d}m"


def render_line(state: ProgressState, width: int) -> str:
    """The bar and the counts, fitted to `width`: the bar shrinks first, then the counts
    from the right are left out."""
    fields = [f"{state.done}/{state.total}", f"passed {state.passed}",
              f"failed {state.failed}", f"errors {state.errors}"]
    fields += [f"timeouts {state.timeouts}"] * bool(state.timeouts)
    fields += [f"cancelled {state.cancelled}"] * bool(state.cancelled)
    fields += [f"running {state.running}", f"queued {state.queued}"]
    if (left := state.left_s) is not None:
        fields.append(f"~{span(left)} left")
    text = "  ".join(fields)
    room = min(BAR, width - len(text) - 3)  # "[" + bar + "] "
    if room >= NARROWEST_BAR:
        filled = state.done * room // state.total if state.total else room
        return f"[{'█' * filled}{'░' * (room - filled)}] {text}"
    while len(text) > width and len(fields) > 1:
        fields.pop()
        text = "  ".join(fields)
    return text[:width]


def render_finished(plan: JobPlan, result: JobResult) -> str:
    """`FAIL  drive[world=a.sdf, seed=7]  11.2 s  node 10.0.0.2: why (log: jobs/drive-…/)`"""
    reason = (result.reason.strip().splitlines() or [""])[0]  # the log holds the rest
    said = ": ".join(part for part in (result.node and f"node {result.node}", reason) if part)
    log = f" (log: {result.log})" if result.log else ""
    return f"{result.status.name}  {plan.title}  {result.wall_s:.1f} s  {said}".rstrip() + log


class Progress:
    """Prints the progress of one batch to `stream`."""

    def __init__(self, stream: TextIO, interactive: bool, *, width: int | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.stream = stream
        self.interactive = interactive
        self.width = width
        self.clock = clock
        self._shown: ProgressState | None = None  # the bar on screen, to redraw
        self._next_log = clock() + LOG_EVERY

    def update(self, state: ProgressState) -> None:
        if self.interactive:
            self._shown = state
            self._write(CLEAR + render_line(state, self._columns()))
        elif (now := self.clock()) >= self._next_log:
            self._next_log = now + LOG_EVERY
            self._write(render_line(state, self._columns()) + "\n")

    def finished(self, plan: JobPlan, result: JobResult) -> None:
        passed = result.status is Status.PASS
        if passed and self.interactive:
            return
        line = f"pass  {plan.title}  {result.wall_s:.1f} s" if passed else \
            render_finished(plan, result)
        if not self.interactive:
            self._write(line + "\n")
            return
        redraw = render_line(self._shown, self._columns()) if self._shown else ""
        self._write(f"{CLEAR}{line}\n{redraw}")

    def close(self) -> None:
        """Ends the bar's line, leaving the last state on screen."""
        if self._shown is not None:
            self._write("\n")
            self._shown = None

    def _columns(self) -> int:
        if self.width is not None:
            return self.width
        return shutil.get_terminal_size().columns if self.interactive else 120

    def _write(self, text: str) -> None:
        self.stream.write(text)
        self.stream.flush()
