"""A system that publishes a reading at its rate, on the grid of sim/schedule.py, and only
while someone subscribes, as Gazebo's state publishers do (joint_state.py, classic_state.py)."""

from __future__ import annotations

from typing import Any

from launcher.sim import schedule
from launcher.sim.plugins import Plugin


class PeriodicPublisher(Plugin):
    rate = 0.0  # readings a second (0: every step)
    publisher: Any = None

    def reset(self) -> None:
        self.next_update = 0.0

    def post_step(self, model: Any, data: Any) -> None:
        if schedule.tick(self, data.time, self.rate) and \
                self.publisher.get_subscription_count():
            self.publisher.publish(self.measure(model, data))

    def measure(self, model: Any, data: Any) -> Any:
        """The message to publish now."""
        raise NotImplementedError
