"""When a periodic system or sensor runs next, in sim time: one grid for all of them.

Each keeps `next_update` (the sim's stepping calls its post_step once that time has come).
The next time is the next point of the grid of its period, as gz-sensors schedules a sensor:
a step that lands late does not push the grid on, so a rate that is no multiple of the
timestep keeps its average (30 Hz on a 1 ms step is 30 updates a second, not 29.4), and a
system that fell more than a period behind restarts the grid from now instead of catching up
in a burst. Work that waits for a subscriber looks again every LAZY_LOOK seconds."""

from __future__ import annotations

import math
from typing import Any

LAZY_LOOK = 0.05  # s of sim time between looks for a subscriber, while there is none
SLACK = 1e-9  # s: a step's time within this of a due time is on it (float sums of the step)


def period(rate: float) -> float:
    """The period of `rate` per second; 0 (every step) for a rate of 0 or less."""
    return 1.0 / rate if rate > 0 else 0.0


def is_due(now: float, next_update: float) -> bool:
    return now + SLACK >= next_update


def following(next_update: float, now: float, every: float) -> float:
    """The first point of the grid of `every` seconds (through `next_update`) after `now`;
    `now` itself (the next step) for a period of 0, never for an infinite one."""
    if every <= 0:
        return now
    if every == math.inf:
        return math.inf
    due = max(next_update, now - every)
    while due <= now + SLACK:
        due += every
    return due


def tick(owner: Any, now: float, rate: float) -> bool:
    """Whether `owner`'s work of `rate` per second is due at `now`; when it is, its
    `next_update` moves on to the next time."""
    if not is_due(now, owner.next_update):
        return False
    owner.next_update = following(owner.next_update, now, period(rate))
    return True


def serve(owner: Any, now: float, every: float, wanted: bool) -> bool:
    """A sensor's turn: with someone to work for (`wanted`), its next time on the grid of
    `every` and True; with none, a look again after LAZY_LOOK at least, and False."""
    if not wanted:
        owner.next_update = idle(now, every)
        return False
    owner.next_update = following(owner.next_update, now, every)
    return True


def idle(now: float, every: float) -> float:
    """When to look again for someone to work for, with none now."""
    return now + max(every, LAZY_LOOK)
