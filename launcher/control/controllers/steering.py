"""Steered bases, as ros2_controllers' tricycle_controller and steering_controllers_library's
ackermann_steering_controller.

tricycle_controller/TricycleController: `traction_joint_name` (velocity), `steering_joint_name`
(position), `wheel_radius`, `wheelbase`, `odom_frame_id`, `base_frame_id`, `enable_odom_tf`,
`cmd_vel_timeout` (milliseconds, 500, as tricycle_controller has it), `use_stamped_vel`,
`traction.max_velocity` and `steering.max_position` limits; `~/cmd_vel` (TwistStamped),
`~/odom`, `/tf`. A turn in place points the wheel sideways, as tricycle_controller does.

ackermann_steering_controller/AckermannSteeringController: `rear_wheels_names` (velocity),
`front_wheels_names` (position), `wheelbase`, `front_wheel_track`, `rear_wheel_track`,
`front_wheels_radius`, `rear_wheels_radius`, `open_loop`, `position_feedback`,
`reference_timeout` (s), `odom_frame_id`, `base_frame_id`, `enable_odom_tf`; `~/reference`
(TwistStamped), `~/odometry`, `~/tf_odometry`. Each front wheel is steered to its own
Ackermann angle and each rear wheel turns at its own radius' speed.

A command holding NaN or an infinity is refused (one warning); the last good one stands.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.bus.declarations import REQUIRED, Param
from launcher.control.controller import Controller, ControllerError
from launcher.control.controllers import odometry

# what both read
COMMON = (
    Param("odom_frame_id", "string", "odom", "the odometry's frame"),
    Param("base_frame_id", "string", "base_link", "the robot's frame"),
    Param("enable_odom_tf", "bool", True, "publish odom -> base"),
    Param("use_stamped_vel", "bool", True, "the command is a TwistStamped (false: a Twist)"),
)


class _Steered(Controller):
    """What both share: a command with a timeout, odometry integrated from (v, w)."""

    command_topic = "~/cmd_vel"
    odom_topic, tf_topic = "~/odom", "/tf"

    def _common(self, p: dict[str, Any], timeout: float) -> None:
        self.odom_frame, self.base_frame = p["odom_frame_id"], p["base_frame_id"]
        self.tf_enabled = p["enable_odom_tf"]
        self.timeout = timeout
        stamped = p["use_stamped_vel"]
        self.cmd_sub = self.node.create_subscription(
            "geometry_msgs/msg/TwistStamped" if stamped else "geometry_msgs/msg/Twist",
            self.command_topic, (lambda m: self._take(m.twist)) if stamped else self._take, 10)
        self.odom_pub = self.node.create_publisher("nav_msgs/msg/Odometry", self.odom_topic, 10)
        self.tf_pub = self.node.create_publisher("tf2_msgs/msg/TFMessage", self.tf_topic, 10)

    def on_cleanup(self) -> None:
        for entity in (self.cmd_sub, self.odom_pub, self.tf_pub):
            entity.destroy()

    def _reset(self) -> None:
        self.target = (0.0, 0.0)
        self.last_command = -math.inf
        self.now = self.x = self.y = self.heading = self.v = self.w = 0.0

    def _take(self, twist: Any) -> None:
        if not self.is_active:
            return
        values = [twist.linear.x, twist.angular.z]
        if self.refuse_non_finite(values, f"a command on {self.command_topic}"):
            return
        self.target, self.last_command = (values[0], values[1]), self.now

    def _wanted(self, time: float) -> tuple[float, float]:
        self.now = time
        if self.timeout > 0 and time - self.last_command > self.timeout:
            self.target = (0.0, 0.0)
        return self.target

    def _integrate(self, v: float, w: float, period: float) -> None:
        self.v, self.w = v, w
        heading = self.heading + w * period / 2
        self.x += v * period * math.cos(heading)
        self.y += v * period * math.sin(heading)
        self.heading = math.atan2(math.sin(self.heading + w * period),
                                  math.cos(self.heading + w * period))

    def _publish(self, time: float) -> None:
        odometry.publish(self, time, self.x, self.y, self.heading, self.v, self.w)


class TricycleController(_Steered):
    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("traction_joint_name", "string", REQUIRED, "the driven wheel's joint (velocity)"),
        Param("steering_joint_name", "string", REQUIRED, "the steering joint (position)"),
        Param("wheel_radius", "double", REQUIRED, "the driven wheel's radius, m", above=0.0),
        Param("wheelbase", "double", REQUIRED, "from the steered wheel to the rear axle, m",
              above=0.0),
        Param("traction.max_velocity", "double", math.inf, "the wheel's largest speed, rad/s"),
        Param("steering.max_position", "double", math.pi / 2,
              "the largest steering angle, rad"),
        Param("cmd_vel_timeout", "double", 500.0,
              "ms without a command before the robot stops"),
        *COMMON,
    )

    def on_init(self) -> None:
        p = self.read_parameters("traction_joint_name", "steering_joint_name")
        self.traction, self.steering = p["traction_joint_name"], p["steering_joint_name"]

    def command_interfaces(self) -> list[str]:
        return [f"{self.traction}/velocity", f"{self.steering}/position"]

    def state_interfaces(self) -> list[str]:
        return [f"{self.traction}/velocity", f"{self.steering}/position"]

    def on_configure(self) -> None:
        p = self.read_parameters()
        self.radius, self.wheelbase = p["wheel_radius"], p["wheelbase"]
        self.max_speed = p["traction.max_velocity"]
        self.max_angle = p["steering.max_position"]
        self._common(p, p["cmd_vel_timeout"] / 1000.0)

    def on_activate(self) -> None:
        self._reset()
        self.speed_state = self.states[f"{self.traction}/velocity"]
        self.angle_state = self.states[f"{self.steering}/position"]

    def update(self, time: float, period: float) -> None:
        v, w = self._wanted(time)
        if v == 0 and w != 0:  # in place: the wheel sideways
            angle = math.copysign(math.pi / 2, w)
            speed = abs(w) * self.wheelbase / self.radius
        elif v != 0:
            angle = math.atan(w * self.wheelbase / v)
            speed = v / (self.radius * math.cos(angle))
        else:
            angle = speed = 0.0
        angle = max(-self.max_angle, min(self.max_angle, angle))
        speed = max(-self.max_speed, min(self.max_speed, speed))
        self.commands[0].value, self.commands[1].value = speed, angle
        measured, steer = self.speed_state.value * self.radius, self.angle_state.value
        self._integrate(measured * math.cos(steer), measured * math.sin(steer) / self.wheelbase,
                        period)
        self._publish(time)


class AckermannSteeringController(_Steered):
    command_topic = "~/reference"
    odom_topic, tf_topic = "~/odometry", "~/tf_odometry"

    PARAMETERS = (
        *Controller.PARAMETERS,
        Param("rear_wheels_names", "string_array", REQUIRED,
              "the rear wheels' joints, left then right (velocity)", non_empty=True),
        Param("front_wheels_names", "string_array", REQUIRED,
              "the front wheels' joints, left then right (position)", non_empty=True),
        Param("position_feedback", "bool", False,
              "odometry from the rear wheels' positions (false: their velocities)"),
        Param("wheelbase", "double", REQUIRED, "from the front to the rear axle, m"),
        Param("front_wheel_track", "double", REQUIRED, "between the front wheels, m"),
        Param("rear_wheel_track", "double", REQUIRED, "between the rear wheels, m"),
        Param("front_wheels_radius", "double", 0.0, "accepted: the front wheels are steered"),
        Param("rear_wheels_radius", "double", REQUIRED, "the rear wheels' radius, m"),
        Param("open_loop", "bool", False, "odometry from the commands, not the wheels"),
        Param("reference_timeout", "double", 1.0,
              "s without a command before the robot stops"),
        *COMMON,
    )

    def on_init(self) -> None:
        p = self.read_parameters("rear_wheels_names", "front_wheels_names",
                                 "position_feedback")
        self.rear, self.front = p["rear_wheels_names"], p["front_wheels_names"]
        if len(self.rear) != 2 or len(self.front) != 2:
            raise ControllerError(self._at(f"controller '{self.name}': an Ackermann base has "
                                           f"two rear and two front wheels (left, right)"))
        self.position_feedback = p["position_feedback"]

    def command_interfaces(self) -> list[str]:
        return [f"{w}/velocity" for w in self.rear] + [f"{w}/position" for w in self.front]

    def state_interfaces(self) -> list[str]:
        kind = "position" if self.position_feedback else "velocity"
        return [f"{w}/{kind}" for w in self.rear] + [f"{w}/position" for w in self.front]

    def on_configure(self) -> None:
        p = self.read_parameters()
        self.wheelbase, self.rear_radius = p["wheelbase"], p["rear_wheels_radius"]
        self.front_track, self.rear_track = p["front_wheel_track"], p["rear_wheel_track"]
        self.open_loop = p["open_loop"]
        self._common(p, p["reference_timeout"])

    def on_activate(self) -> None:
        self._reset()
        self.previous: list[float] | None = None

    def update(self, time: float, period: float) -> None:
        v, w = self._wanted(time)
        half_front, half_rear = self.front_track / 2, self.rear_track / 2
        if abs(w) < 1e-9 or v == 0:
            angles = [0.0, 0.0]
            speeds = [v / self.rear_radius] * 2
        else:
            radius = v / w  # of the base's centre of the rear axle
            angles = [math.atan(self.wheelbase / (radius - half_front)),
                      math.atan(self.wheelbase / (radius + half_front))]
            speeds = [w * (radius - half_rear) / self.rear_radius,
                      w * (radius + half_rear) / self.rear_radius]
        for handle, value in zip(self.commands, speeds + angles, strict=True):
            handle.value = value
        if self.open_loop:
            self._integrate(v, w, period)
        else:
            rear = [self.states[n].value for n in self.state_interfaces()[:2]]
            if self.position_feedback:
                if self.previous is None:
                    self.previous = rear
                turned = [(a - b) / period if period > 0 else 0.0
                          for a, b in zip(rear, self.previous, strict=True)]
                self.previous = rear
                rear = turned
            left, right = (s * self.rear_radius for s in rear)
            self._integrate((left + right) / 2, (right - left) / self.rear_track, period)
        self._publish(time)
