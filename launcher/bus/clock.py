"""A node's clock: wall time, or the last `/clock` message when `use_sim_time` is true.

Sim time advances when the node's executor delivers `/clock` (as with rclpy); before the
first message it reads zero. A timer given this clock keeps sim time (timer.py); others, and
Rate, keep the monotonic clock.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from launcher.bus.qos import QoS
from launcher.bus.wire import stamp_nanoseconds
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
    def __init__(self, node: Any, use_sim_time: bool,
                 sim_time: Callable[[], float] | None = None) -> None:
        """`sim_time`: the sim's own time (seconds), for a node inside the sim: read when
        asked, nothing subscribed (the sim's /clock would come back to it through the bus)."""
        self.use_sim_time = use_sim_time
        self._sim_ns = 0
        self._follower: Any = None  # its node's part in a sim's lockstep (lockstep.py)
        self._source = sim_time if use_sim_time else None
        if use_sim_time and sim_time is None:
            from launcher.bus.lockstep import Follower

            node.create_subscription("rosgraph_msgs/msg/Clock", "/clock", self._on_clock,
                                     QoS(depth=1, reliable=False))
            self._follower = node.host.adopt(Follower(node.host))

    def _on_clock(self, message: Any) -> None:
        self._sim_ns = stamp_nanoseconds(message.clock)
        if self._follower is not None:
            self._follower.clock(self._sim_ns)

    @property
    def source(self) -> Callable[[], float] | None:
        """The sim's own time this clock reads (a node inside the sim), or None."""
        return self._source

    def caught_up(self) -> None:
        """The node's executor has nothing left to do (a sim in lockstep is told so)."""
        if self._follower is not None:
            self._follower.caught_up()

    def now(self) -> Time:
        if self._source is not None:
            return Time(round(self._source() * 1e9))
        return Time(self._sim_ns if self.use_sim_time else time.time_ns())
