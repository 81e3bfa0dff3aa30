"""rclpy.time_source.TimeSource: sets the ROS time of the clocks attached to it from a node's
`/clock` while the node's use_sim_time is true, so that their jump callbacks run.

A node's own clock reads launcher's bus clock, which follows `/clock` by itself; the node
makes a TimeSource for it only when a jump callback is asked for (clock.py).
"""

from __future__ import annotations

from typing import Any

from rclpy.clock import ROSClock
from rclpy.clock_type import ClockType
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.time import Time

__all__ = ["CLOCK_TOPIC", "USE_SIM_TIME_NAME", "ClockType", "TimeSource"]

CLOCK_TOPIC = "/clock"
USE_SIM_TIME_NAME = "use_sim_time"


class TimeSource:
    """The ROS time of its clocks, from its node's /clock when ROS time is active."""

    def __init__(self, *, node: Any = None) -> None:
        self._clocks: set[ROSClock] = set()
        self._node: Any = None
        self._subscription: Any = None
        self._active = False
        self._last: Time | None = None
        if node is not None:
            self.attach_node(node)

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the clocks follow /clock."""
        return self._active

    @ros_time_is_active.setter
    def ros_time_is_active(self, enabled: bool) -> None:
        self._active = bool(enabled)
        for clock in self._clocks:
            clock.set_ros_time_is_active(self._active)
        if self._active and self._subscription is None and self._node is not None:
            from rosgraph_msgs.msg import Clock as ClockMessage

            self._subscription = self._node.create_subscription(
                ClockMessage, CLOCK_TOPIC, self.clock_callback,
                QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT))

    def attach_node(self, node: Any) -> None:
        """Follow `node`'s /clock while its use_sim_time parameter is true."""
        if self._node is not None:
            self.detach_node()
        self._node = node
        if not node.has_parameter(USE_SIM_TIME_NAME):
            node.declare_parameter(USE_SIM_TIME_NAME, False)
        value = node.get_parameter(USE_SIM_TIME_NAME).value
        if not isinstance(value, bool):
            raise ValueError(f"{USE_SIM_TIME_NAME} parameter set to something besides a bool")
        node.add_on_set_parameters_callback(self._on_set)
        self.ros_time_is_active = value

    def _on_set(self, parameters: list[Parameter]) -> Any:
        from rcl_interfaces.msg import SetParametersResult

        for parameter in parameters:
            if parameter.name == USE_SIM_TIME_NAME:
                if parameter.type_ != Parameter.Type.BOOL:
                    return SetParametersResult(
                        successful=False, reason=f"{USE_SIM_TIME_NAME} must be a bool")
                self.ros_time_is_active = parameter.value
        return SetParametersResult(successful=True)

    def detach_node(self) -> None:
        """Stop following the node's /clock."""
        if self._node is not None:
            if self._subscription is not None:
                self._node.destroy_subscription(self._subscription)
            self._node.remove_on_set_parameters_callback(self._on_set)
        self._node, self._subscription = None, None

    def attach_clock(self, clock: ROSClock) -> None:
        """Set `clock`'s ROS time from now on (TypeError for a clock not of ROS time)."""
        if not isinstance(clock, ROSClock):
            raise ValueError("Only clocks with type ROS_TIME can be attached.")
        if self._last is not None:
            clock.set_ros_time(self._last.nanoseconds)
        clock.set_ros_time_is_active(self._active)
        self._clocks.add(clock)

    def clock_callback(self, msg: Any) -> None:
        """A /clock message: the clocks' new ROS time."""
        self._last = Time.from_msg(msg.clock)
        for clock in self._clocks:
            clock.set_ros_time(self._last.nanoseconds)


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
