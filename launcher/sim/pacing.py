"""Pacing physics to real time × RTF against a monotonic clock.

The pacer keeps an anchor (wall time, step count) and says how many steps are due: it never
sleeps a fixed amount per step, so rounding never accumulates into drift. After a stall longer
than MAX_LAG of wall time (a slow spawn, a paused debugger), it re-anchors instead of running
fast to catch up. RTF 0 means as fast as possible.
"""

from __future__ import annotations

import time
from collections.abc import Callable

MAX_LAG = 0.25  # s of wall time behind before re-anchoring


class Pacer:
    def __init__(self, timestep: float, rtf: float,
                 clock: Callable[[], float] = time.monotonic) -> None:
        if rtf < 0:
            raise ValueError(f"the real-time factor must be >= 0, got {rtf}")
        self.timestep, self.rtf, self.clock = timestep, rtf, clock
        self.reanchors = 0
        self.restart()

    def restart(self) -> None:
        """Anchor now (at start, on unpause, after a reset or a stall)."""
        self._wall = self.clock()
        self._steps = 0

    def due(self) -> int:
        """Steps to run now to be on schedule (0: ahead of schedule)."""
        if self.rtf == 0:
            return 1 << 30
        elapsed = self.clock() - self._wall
        target = int(elapsed * self.rtf / self.timestep + 1e-9)
        behind = target - self._steps
        if behind * self.timestep / self.rtf > MAX_LAG:
            self._wall = self.clock() - self._steps * self.timestep / self.rtf
            self.reanchors += 1
            return 1
        return max(0, behind)

    def wait_time(self) -> float:
        """Seconds until the next step is due."""
        if self.rtf == 0:
            return 0.0
        next_wall = self._wall + (self._steps + 1) * self.timestep / self.rtf
        return max(0.0, next_wall - self.clock())

    def stepped(self, count: int) -> None:
        self._steps += count
