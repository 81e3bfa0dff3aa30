"""diff_drive_controller/DiffDriveController: `~/cmd_vel` (geometry_msgs/TwistStamped; Twist
with `use_stamped_vel: false`) to the wheels' velocity command interfaces, odometry on `~/odom`
(nav_msgs/Odometry) and odom → base on `/tf`, as ros2_controllers' does.

Parameters: `left_wheel_names`, `right_wheel_names`, `wheel_separation`, `wheel_radius`,
`wheels_per_side`, `wheel_separation_multiplier`, `left_wheel_radius_multiplier`,
`right_wheel_radius_multiplier`, `odom_frame_id` (odom), `base_frame_id` (base_link),
`pose_covariance_diagonal`, `twist_covariance_diagonal`, `open_loop` (odometry from the
commands instead of the wheels), `position_feedback` (wheel positions, else velocities),
`enable_odom_tf`, `cmd_vel_timeout` (0.5 s: the robot stops), `publish_rate` (50 Hz),
`tf_frame_prefix_enable` / `tf_frame_prefix`, `velocity_rolling_window_size`, and the limits
`linear.x.*` and `angular.z.*` (`has_velocity_limits`, `has_acceleration_limits`,
`max_velocity`, `min_velocity`, `max_acceleration`, `min_acceleration`; jerk limits are
accepted and not applied). A command holding NaN or an infinity is refused.
"""

from __future__ import annotations

import math
from collections import deque
from typing import Any

from launcher.bus.declarations import REQUIRED, Param
from launcher.control.controller import Controller
from launcher.control.controllers import odometry


def limit_parameters(axis: str, what: str) -> tuple[Param, ...]:
    """The limits of one axis, as ros2_controllers' speed limiter reads them."""
    return (
        Param(f"{axis}.has_velocity_limits", "bool", False, f"limit the {what} velocity"),
        Param(f"{axis}.has_acceleration_limits", "bool", False,
              f"limit the {what} acceleration"),
        Param(f"{axis}.has_jerk_limits", "bool", False, "accepted; jerk is not limited"),
        Param(f"{axis}.max_velocity", "double", math.inf, f"the largest {what} velocity"),
        Param(f"{axis}.min_velocity", "double", math.nan,
              f"the smallest {what} velocity (NaN: -max_velocity)"),
        Param(f"{axis}.max_acceleration", "double", math.inf,
              f"the largest {what} acceleration"),
        Param(f"{axis}.min_acceleration", "double", math.nan,
              f"the smallest {what} acceleration (NaN: -max_acceleration)"),
        Param(f"{axis}.max_jerk", "double", math.inf, "accepted; jerk is not limited"),
        Param(f"{axis}.min_jerk", "double", math.nan, "accepted; jerk is not limited"),
    )


class Limit:
    def __init__(self, values: dict[str, Any], axis: str) -> None:
        self.velocity = values[f"{axis}.has_velocity_limits"]
        self.acceleration = values[f"{axis}.has_acceleration_limits"]
        self.max_v = values[f"{axis}.max_velocity"]
        self.min_v = values[f"{axis}.min_velocity"]
        self.max_a = values[f"{axis}.max_acceleration"]
        self.min_a = values[f"{axis}.min_acceleration"]
        if math.isnan(self.min_v):
            self.min_v = -self.max_v
        if math.isnan(self.min_a):
            self.min_a = -self.max_a

    def limit(self, target: float, current: float, dt: float) -> float:
        value = target
        if self.velocity:
            value = min(max(value, self.min_v), self.max_v)
        if self.acceleration and dt > 0:
            value = min(max(value, current + self.min_a * dt), current + self.max_a * dt)
        return value


class DiffDriveController(Controller):
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("left_wheel_names", "string_array", REQUIRED, "the left wheels' joints",
              non_empty=True),
        Param("right_wheel_names", "string_array", REQUIRED, "the right wheels' joints",
              non_empty=True),
        Param("position_feedback", "bool", True,
              "odometry from the wheels' positions (false: their velocities)"),
        Param("wheel_separation", "double", REQUIRED,
              "the distance between the left and right wheels, m", above=0.0),
        Param("wheel_radius", "double", REQUIRED, "the wheels' radius, m", above=0.0),
        Param("wheels_per_side", "int", 0, "accepted: every named wheel is driven"),
        Param("wheel_separation_multiplier", "double", 1.0, "corrects wheel_separation"),
        Param("left_wheel_radius_multiplier", "double", 1.0, "corrects the left radius"),
        Param("right_wheel_radius_multiplier", "double", 1.0, "corrects the right radius"),
        Param("open_loop", "bool", False, "odometry from the commands, not the wheels"),
        Param("enable_odom_tf", "bool", True, "publish odom -> base on /tf"),
        Param("cmd_vel_timeout", "double", 0.5,
              "s without a command before the robot stops (0 or less: never)"),
        Param("publish_rate", "double", 50.0,
              "odometry messages a second (0 or less: every update)"),
        Param("tf_frame_prefix_enable", "bool", True, "prefix the frames"),
        Param("tf_frame_prefix", "string", "", "the prefix (empty: the node's namespace)"),
        Param("odom_frame_id", "string", "odom", "the odometry's frame"),
        Param("base_frame_id", "string", "base_link", "the robot's frame"),
        Param("pose_covariance_diagonal", "double_array", [0.0] * 6,
              "the pose covariance's diagonal (x, y, z, roll, pitch, yaw)"),
        Param("twist_covariance_diagonal", "double_array", [0.0] * 6,
              "the twist covariance's diagonal"),
        Param("velocity_rolling_window_size", "int", 10,
              "wheel velocities averaged over this many updates (at least 1)"),
        Param("use_stamped_vel", "bool", True,
              "~/cmd_vel is a TwistStamped (false: a Twist)"),
        *limit_parameters("linear.x", "linear"),
        *limit_parameters("angular.z", "angular"),
    )

    def on_init(self) -> None:
        values = self.read_parameters("left_wheel_names", "right_wheel_names",
                                      "position_feedback")
        self.left, self.right = values["left_wheel_names"], values["right_wheel_names"]
        self.position_feedback = values["position_feedback"]

    def command_interfaces(self) -> list[str]:
        return [f"{w}/velocity" for w in self.left + self.right]

    def state_interfaces(self) -> list[str]:
        kind = "position" if self.position_feedback else "velocity"
        return [f"{w}/{kind}" for w in self.left + self.right]

    def on_configure(self) -> None:
        p = self.read_parameters()
        separation, radius = p["wheel_separation"], p["wheel_radius"]
        self.separation = separation * p["wheel_separation_multiplier"]
        self.left_radius = radius * p["left_wheel_radius_multiplier"]
        self.right_radius = radius * p["right_wheel_radius_multiplier"]
        self.open_loop, self.tf_enabled = p["open_loop"], p["enable_odom_tf"]
        self.timeout = p["cmd_vel_timeout"]
        rate = p["publish_rate"]
        self.publish_period = 1.0 / rate if rate > 0 else 0.0
        prefix = ""
        if p["tf_frame_prefix_enable"]:
            prefix = p["tf_frame_prefix"] or self.node.namespace.strip("/")
            prefix = f"{prefix.strip('/')}/" if prefix.strip("/") else ""
        self.odom_frame = prefix + p["odom_frame_id"]
        self.base_frame = prefix + p["base_frame_id"]
        self.pose_covariance = p["pose_covariance_diagonal"]
        self.twist_covariance = p["twist_covariance_diagonal"]
        self.window = max(p["velocity_rolling_window_size"], 1)
        self.linear_limit = Limit(p, "linear.x")
        self.angular_limit = Limit(p, "angular.z")
        stamped = p["use_stamped_vel"]
        node = self.node
        self.cmd_sub = node.create_subscription(
            "geometry_msgs/msg/TwistStamped" if stamped else "geometry_msgs/msg/Twist",
            "~/cmd_vel", self.on_stamped if stamped else self.on_twist, 10)
        self.odom_pub = node.create_publisher("nav_msgs/msg/Odometry", "~/odom", 10)
        self.tf_pub = node.create_publisher("tf2_msgs/msg/TFMessage", "/tf", 10)

    def on_cleanup(self) -> None:
        for entity in (self.cmd_sub, self.odom_pub, self.tf_pub):
            entity.destroy()

    def on_activate(self) -> None:
        count = len(self.left)
        self.left_cmd, self.right_cmd = self.commands[:count], self.commands[count:]
        handles = [self.states[name] for name in self.state_interfaces()]
        self.left_state, self.right_state = handles[:count], handles[count:]
        self.target = (0.0, 0.0)
        self.command = (0.0, 0.0)
        self.last_command_time = -math.inf
        self.x = self.y = self.heading = 0.0
        self.linear = self.angular = 0.0
        self.previous: tuple[float, float] | None = None
        self.speeds: deque[tuple[float, float]] = deque(maxlen=self.window)
        self.next_publish = 0.0
        self.now = 0.0

    def on_deactivate(self) -> None:
        for handle in self.commands:
            handle.value = 0.0

    # --- commands --------------------------------------------------------------------------
    def on_stamped(self, message: Any) -> None:
        self._take(message.twist)

    def on_twist(self, message: Any) -> None:
        self._take(message)

    def _take(self, twist: Any) -> None:
        if not self.is_active:
            return
        values = [twist.linear.x, twist.angular.z]
        if self.refuse_non_finite(values, "a command on ~/cmd_vel"):
            return
        self.target = (values[0], values[1])
        self.last_command_time = self.now

    # --- the cycle -------------------------------------------------------------------------
    def update(self, time: float, period: float) -> None:
        self.now = time
        if self.timeout > 0 and time - self.last_command_time > self.timeout:
            self.target = (0.0, 0.0)
        self._odometry(time, period)
        linear = self.linear_limit.limit(self.target[0], self.command[0], period)
        angular = self.angular_limit.limit(self.target[1], self.command[1], period)
        self.command = (linear, angular)
        half = angular * self.separation / 2
        left, right = (linear - half) / self.left_radius, (linear + half) / self.right_radius
        for handle in self.left_cmd:
            handle.value = left
        for handle in self.right_cmd:
            handle.value = right
        if self.publish_period and time + 1e-9 >= self.next_publish:
            self.next_publish = time + self.publish_period
            self._publish(time)

    def _odometry(self, time: float, period: float) -> None:
        if self.open_loop:
            linear, angular = self.command
            self._integrate(linear * period, angular * period)
            self.linear, self.angular = linear, angular
            return
        left_values = [h.value for h in self.left_state]
        right_values = [h.value for h in self.right_state]
        left = sum(left_values) / len(left_values)
        right = sum(right_values) / len(right_values)
        if not self.position_feedback:  # wheel speeds: integrate them
            d_left, d_right = left * self.left_radius * period, right * self.right_radius * period
        else:
            if self.previous is None:
                self.previous = (left, right)
                return
            d_left = (left - self.previous[0]) * self.left_radius
            d_right = (right - self.previous[1]) * self.right_radius
            self.previous = (left, right)
        distance, turn = (d_left + d_right) / 2, (d_right - d_left) / self.separation
        self._integrate(distance, turn)
        if period > 0:
            self.speeds.append((distance / period, turn / period))
            self.linear = sum(s[0] for s in self.speeds) / len(self.speeds)
            self.angular = sum(s[1] for s in self.speeds) / len(self.speeds)

    def _integrate(self, distance: float, turn: float) -> None:
        if abs(turn) < 1e-6:  # second-order Runge-Kutta, as ros2_controllers' odometry
            heading = self.heading + turn / 2
            self.x += distance * math.cos(heading)
            self.y += distance * math.sin(heading)
        else:  # the exact arc
            radius = distance / turn
            old = self.heading
            self.x += radius * (math.sin(old + turn) - math.sin(old))
            self.y += -radius * (math.cos(old + turn) - math.cos(old))
        self.heading = math.atan2(math.sin(self.heading + turn), math.cos(self.heading + turn))

    def _publish(self, time: float) -> None:
        odometry.publish(self, time, self.x, self.y, self.heading, self.linear, self.angular,
                         self.pose_covariance, self.twist_covariance)
