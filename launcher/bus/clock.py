"""A node's clock: wall time, or the last `/clock` message when `use_sim_time` is true.

Sim time advances when the node's executor delivers `/clock` (as with rclpy); before the
first message it reads zero. A timer given this clock keeps sim time (timer.py); others, and
Rate, keep the monotonic clock.
"""

from __future__ import annotations

import time
from typing import Any

from launcher.bus.qos import QoS
from launcher.records import dataclass


@dataclass(frozen=True)
class Time:
    nanoseconds: int

    @property
    def seconds(self) -> float:
        return self.nanoseconds / 1e9

    def to_msg(self) -> Any:
        from launcher.bus.messages import build

        sec, nanosec = divmod(self.nanoseconds, 1_000_000_000)
        return build("builtin_interfaces/msg/Time", {"sec": sec, "nanosec": nanosec})


class Clock:
    def __init__(self, node: Any, use_sim_time: bool) -> None:
        self.use_sim_time = use_sim_time
        self._sim_ns = 0
        self._follower: Any = None  # its node's part in a sim's lockstep (lockstep.py)
        if use_sim_time:
            from launcher.bus.lockstep import Follower

            node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", self._on_clock,
                                     QoS(depth=1, reliable=False))
            self._follower = node.host.adopt(Follower(node.host))

    def _on_clock(self, message: Any) -> None:
        self._sim_ns = message.clock.sec * 1_000_000_000 + message.clock.nanosec
        if self._follower is not None:
            self._follower.clock(self._sim_ns)

    def caught_up(self) -> None:
        """The node's executor has nothing left to do (a sim in lockstep is told so)."""
        if self._follower is not None:
            self._follower.caught_up()

    def now(self) -> Time:
        return Time(self._sim_ns if self.use_sim_time else time.time_ns())
