"""`<enable_metrics>`: a sensor's performance, as gz-sensors publishes it on
`<topic>/performance_metrics` after each update (gz.msgs.PerformanceSensorMetrics): its update
rate in sim time and in real time since the last update (0 at the first), its nominal rate,
and, for a camera, its frames a second in real time over the last frames drawn."""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Callable
from typing import Any

MESSAGE = "mujoco_sim/msg/PerformanceSensorMetrics"
SUFFIX = "performance_metrics"
FPS_FRAMES = 10  # frames the fps is averaged over


def enabled(element: Any) -> bool:
    """Whether a `<sensor>` asks for its metrics."""
    return (element.value("enable_metrics", "false") or "").strip().lower() in ("true", "1")


class Metrics:
    def __init__(self, name: str, nominal: float,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.name, self.nominal, self.clock = name, nominal, clock
        self.last_sim = self.last_real = None  # type: float | None
        self.frames: deque[float] = deque(maxlen=FPS_FRAMES)

    def update(self, sim_time: float, frame: bool = False) -> dict[str, Any]:
        """The message's fields for an update at `sim_time` (a camera's: `frame`)."""
        real = self.clock()
        sim_rate = real_rate = 0.0
        if self.last_sim is not None and self.last_real is not None:
            sim_rate = _rate(sim_time - self.last_sim)
            real_rate = _rate(real - self.last_real)
        self.last_sim, self.last_real = sim_time, real
        fps = 0.0
        if frame:
            self.frames.append(real)
            if len(self.frames) > 1:
                fps = _rate((self.frames[-1] - self.frames[0]) / (len(self.frames) - 1))
        return {"name": self.name, "real_update_rate": real_rate,
                "sim_update_rate": sim_rate, "nominal_update_rate": self.nominal, "fps": fps}


def _rate(period: float) -> float:
    return 1.0 / period if period > 0 else float("inf")
