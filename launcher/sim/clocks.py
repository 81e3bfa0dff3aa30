"""The topics the sim says its time on, packed directly (they go out after every batch of steps):
/clock and /world/<w>/clock as mujoco_sim/msg/Clock (Gazebo's: sim time, real time, paused,
iterations), and, when asked, /clock as rosgraph_msgs/Clock on the ROS graph. A topic nobody
subscribes to is not written."""

from __future__ import annotations

import time
from typing import Any

from launcher.bus import keys
from launcher.bus.wire import clock_cdr, ros_clock_cdr

CLOCK = "mujoco_sim/msg/Clock"


class Clocks:
    def __init__(self, node: Any, world_name: str) -> None:
        self.node = node
        self._clocks = [node.create_publisher(CLOCK, "/clock")]  # then the world's (name())
        self._ros_clocks: list[Any] = []
        self.name(world_name)
        self._started = time.monotonic()  # real time counts from here

    def name(self, world_name: str) -> None:
        """The world's clock under `/world/<world_name>/`, in place of the last world's."""
        for clock in self._clocks[1:]:
            clock.destroy()
        self._clocks[1:] = [self.node.create_publisher(CLOCK, f"/world/{world_name}/clock")]

    def add_ros_clock(self) -> None:
        """/clock as rosgraph_msgs/Clock on the ROS graph too (for a sim started without a
        bridge, as mujoco_ros2_control's node publishes it)."""
        self._ros_clocks.append(self.node.create_publisher("rosgraph_msgs/msg/Clock", "/clock",
                                                           space=keys.ROS))

    def publish(self, world: Any, paused: bool) -> None:
        for publisher in self._ros_clocks:
            if publisher.get_subscription_count():
                publisher.publish_raw(ros_clock_cdr(world.data.time))
        wanted = [p for p in self._clocks if p.get_subscription_count()]
        if not wanted:
            return
        payload = clock_cdr(world.data.time, time.monotonic() - self._started, paused,
                            world.physics.iterations)
        for publisher in wanted:
            publisher.publish_raw(payload)
