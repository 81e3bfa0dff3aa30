"""The sim's report: what a run came to, written as JSON when the sim exits, for the launch or
batch that started it to read (`launcher launch --sim-duration`, `launcher batch`).

`<folder>/sim-<pid>.json` holds the world file, the seed, the lockstep tick (null when paced),
the sim time (to the nanosecond, as the clocks say it), the steps stepped, the wall time from
the start of the first step to the end of the last and the real-time factor over it, the
world's state digest (World.state_digest: two runs that agree on it ended in the same state),
and whether the sim stopped at its stop time (LAUNCHER_SIM_STOP_AT) rather than on a signal or
an error. It is written to a temporary file and renamed, so a reader never sees half of it.
"""

from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any


@dataclass
class Tally:
    """The steps stepped, and the monotonic times of the first one's start and the last one's
    end."""

    steps: int = 0
    first: float | None = None
    last: float = 0.0

    def stepped(self, count: int, began: float, ended: float) -> None:
        if self.first is None:
            self.first = began
        self.steps += count
        self.last = ended

    @property
    def wall(self) -> float:
        """Seconds of wall time from the first step to the last (0 before one)."""
        return 0.0 if self.first is None else self.last - self.first


@dataclass(frozen=True)
class SimReport:
    """Where the report goes, and what the sim knew of its run before it ran."""

    folder: Path
    world: str
    seed: int
    lockstep_tick: float | None

    @property
    def path(self) -> Path:
        return self.folder / f"sim-{os.getpid()}.json"

    def values(self, world: Any, tally: Tally, stopped: bool) -> dict[str, Any]:
        sim_time = round(float(world.data.time), 9)
        wall = tally.wall
        return {"world": self.world, "seed": self.seed, "lockstep_tick": self.lockstep_tick,
                "sim_time": sim_time, "steps": tally.steps, "stepping_wall_s": wall,
                "rtf": sim_time / wall if wall > 0 else 0.0, "state": world.state_digest(),
                "stopped": stopped}

    def write(self, world: Any, tally: Tally, stopped: bool) -> Path:
        """Write the report of `world` now (atomically); its path."""
        self.folder.mkdir(parents=True, exist_ok=True)
        text = json.dumps(self.values(world, tally, stopped), indent=1) + "\n"
        handle, temporary = tempfile.mkstemp(prefix=".sim-", suffix=".json", dir=self.folder)
        try:
            with os.fdopen(handle, "w", encoding="utf-8") as out:
                out.write(text)
            os.replace(temporary, self.path)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise
        return self.path
