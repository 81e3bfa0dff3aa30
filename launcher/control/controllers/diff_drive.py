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

from launcher.control.controller import Controller, ControllerError
from launcher.control.controllers import odometry


class Limit:
    def __init__(self, controller: Controller, axis: str) -> None:
        p = controller.param

        def number(name: str, default: float) -> float:
            value = p(f"{axis}.{name}", default, (int, float))
            return float(value) if value is not None else default

        self.velocity = bool(p(f"{axis}.has_velocity_limits", False, bool))
        self.acceleration = bool(p(f"{axis}.has_acceleration_limits", False, bool))
        self.max_v = number("max_velocity", math.inf)
        self.min_v = number("min_velocity", math.nan)
        self.max_a = number("max_acceleration", math.inf)
        self.min_a = number("min_acceleration", math.nan)
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
    def on_init(self) -> None:
        self.left = self.names("left_wheel_names")
        self.right = self.names("right_wheel_names")
        self.position_feedback = bool(self.param("position_feedback", True, bool))

    def command_interfaces(self) -> list[str]:
        return [f"{w}/velocity" for w in self.left + self.right]

    def state_interfaces(self) -> list[str]:
        kind = "position" if self.position_feedback else "velocity"
        return [f"{w}/{kind}" for w in self.left + self.right]

    def on_configure(self) -> None:
        p = self.param
        separation = float(p("wheel_separation", kind=(int, float), required=True))
        radius = float(p("wheel_radius", kind=(int, float), required=True))
        if separation <= 0 or radius <= 0:
            raise ControllerError(self._at(f"controller '{self.name}': wheel_separation and "
                                           f"wheel_radius must be positive"))
        self.separation = separation * float(p("wheel_separation_multiplier", 1.0, (int, float)))
        self.left_radius = radius * float(p("left_wheel_radius_multiplier", 1.0, (int, float)))
        self.right_radius = radius * float(p("right_wheel_radius_multiplier", 1.0,
                                             (int, float)))
        self.open_loop = bool(p("open_loop", False, bool))
        self.tf_enabled = bool(p("enable_odom_tf", True, bool))
        self.timeout = float(p("cmd_vel_timeout", 0.5, (int, float)))
        rate = float(p("publish_rate", 50.0, (int, float)))
        self.publish_period = 1.0 / rate if rate > 0 else 0.0
        prefix = ""
        if bool(p("tf_frame_prefix_enable", True, bool)):
            prefix = str(p("tf_frame_prefix", "", str)) or self.node.namespace.strip("/")
            prefix = f"{prefix.strip('/')}/" if prefix.strip("/") else ""
        self.odom_frame = prefix + str(p("odom_frame_id", "odom", str))
        self.base_frame = prefix + str(p("base_frame_id", "base_link", str))
        self.pose_covariance = [float(v) for v in p("pose_covariance_diagonal", [0.0] * 6, list)]
        self.twist_covariance = [float(v) for v in p("twist_covariance_diagonal", [0.0] * 6,
                                                     list)]
        self.window = max(int(p("velocity_rolling_window_size", 10, int)), 1)
        self.linear_limit = Limit(self, "linear.x")
        self.angular_limit = Limit(self, "angular.z")
        stamped = bool(p("use_stamped_vel", True, bool))
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
