"""Ackermann steering (gz-sim-ackermann-steering-system): cmd_vel → rear wheel speeds and front
steering angles, odometry from the wheels, as gz-sim's.

Parameters are gz-sim's, with its defaults: `left_joint`, `right_joint` (repeatable: the
driven wheels), `left_steering_joint`, `right_steering_joint`, `wheel_separation` (1.0),
`kingpin_width` (0.8), `wheel_base` (1.0), `steering_limit` (0.5 rad), `wheel_radius` (0.2),
`steer_p_gain` (1.0: each steering joint turns at gain × its angle error), `steering_only`,
`sub_topic`, `min|max_velocity|acceleration` limits on the speed (jerk limits are accepted,
not applied), and the command and odometry ones every drive has (odometry.py):
`odom_publish_frequency` (50 Hz), `topic` (`cmd_vel`), `odom_topic` (`odometry`), `tf_topic`
(`tf`), `frame_id` (`<name>/odom`), `child_frame_id` (`<name>/<root link>`). Relative topics
live under `/model/<name>/`. The wheels and the steering joints are held at their speeds as gz
holds joint velocity commands; a command with NaN or an infinity is ignored (one warning).
"""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim.plugins import Plugin, PluginError
from launcher.sim.plugins.diff_drive import approach
from launcher.sim.plugins.odometry import (
    OdometryParameters,
    OdometrySchedule,
    open_odometry,
    publish_odometry,
)

CONTROL_PERIOD = 0.005  # s of sim time between updates of the wheel and steering commands
SERVO_TIME = 0.005  # s: the joint velocity servos' settling time (gain from the inertia)


@dataclass
class Parameters(OdometryParameters):
    left_joint: list[str] = attr(Kind.NAMES, required=True)
    right_joint: list[str] = attr(Kind.NAMES, required=True)
    left_steering_joint: list[str] = attr(Kind.NAMES, required=True)
    right_steering_joint: list[str] = attr(Kind.NAMES, required=True)
    wheel_separation: float = attr(Kind.FLOAT, 1.0, above=0.0)
    kingpin_width: float = attr(Kind.FLOAT, 0.8, minimum=0.0)
    wheel_base: float = attr(Kind.FLOAT, 1.0, above=0.0)
    steering_limit: float = attr(Kind.FLOAT, 0.5, above=0.0)
    wheel_radius: float = attr(Kind.FLOAT, 0.2, above=0.0)
    steer_p_gain: float = attr(Kind.FLOAT, 1.0, minimum=0.0)
    steering_only: bool = attr(Kind.BOOL, False)
    sub_topic: str = attr(Kind.TEXT, "")
    min_velocity: float = attr(Kind.FLOAT, -math.inf)
    max_velocity: float = attr(Kind.FLOAT, math.inf)
    min_acceleration: float = attr(Kind.FLOAT, -math.inf)
    max_acceleration: float = attr(Kind.FLOAT, math.inf)
    min_jerk: float = attr(Kind.FLOAT, -math.inf)
    max_jerk: float = attr(Kind.FLOAT, math.inf)
    use_actuator_msg: bool = attr(Kind.BOOL, False)
    actuator_number: int = attr(Kind.INT, 0)


class AckermannSteering(Plugin):
    def prepare(self, spec: Any) -> None:
        p = self.params = self.parameters(Parameters)
        joints = self.joint_names(spec)
        self.wheels = p.left_joint + p.right_joint
        self.steering = [p.left_steering_joint[0], p.right_steering_joint[0]]
        for joint in self.wheels + self.steering:
            if joint not in joints:
                raise PluginError(f"{self.config.where}: plugin {self.label}: joint '{joint}' "
                                  f"is not in the model (joints: {', '.join(joints)})")
        for joint in dict.fromkeys(self.wheels + self.steering):
            actuator = spec.add_actuator(name=self.in_spec(f"ackermann_{joint}"),
                                         target=self.in_spec(joint),
                                         trntype=mujoco.mjtTrn.mjTRN_JOINT)
            actuator.set_to_velocity(kv=1.0)  # the gain is set from the joint at bind
        self.root = self.entity.root.removeprefix(f"{self.entity.name}/")
        self.reset()

    def reset(self) -> None:
        self.target = (0.0, 0.0)
        self.speed = 0.0
        self.x = self.y = self.heading = 0.0
        self.linear = self.angular = 0.0
        self.previous: float | None = None
        self.last_time: float | None = None
        self.odometry = OdometrySchedule(self.params.odom_publish_frequency)
        self.next_update = 0.0

    def load(self) -> None:
        p, name = self.params, self.entity.name
        command = f"/model/{name}/{p.sub_topic.lstrip('/')}" if p.sub_topic and not p.topic \
            else self.topic(p.topic or None, "cmd_vel")
        self.cmd_sub = self.sim.transport.subscribe("mujoco_sim/msg/Twist", command,
                                                    self.on_cmd_vel)
        open_odometry(self, p)

    def bind(self, model: Any, data: Any) -> None:
        prefix = f"{self.entity.name}/"
        self.ids = {}
        for joint in dict.fromkeys(self.wheels + self.steering):
            index = model.joint(prefix + joint).id
            actuator = model.actuator(f"{prefix}ackermann_{joint}").id
            dof = int(model.jnt_dofadr[index])
            gain = float(model.dof_M0[dof]) / SERVO_TIME or 1.0
            model.actuator_gainprm[actuator, 0] = gain
            model.actuator_biasprm[actuator, 2] = -gain
            self.ids[joint] = (int(model.jnt_qposadr[index]), actuator)
        self.data = data

    def on_cmd_vel(self, message: Any) -> None:
        v, w = message.linear.x, message.angular.z
        if not (math.isfinite(v) and math.isfinite(w)):
            self.sim.transport.logger.warning(
                f"entity '{self.entity.name}': ignoring cmd_vel with a NaN or infinite value "
                f"(linear.x={v}, angular.z={w})", once=True)
            return
        self.target = (v, w)
        self.next_update = min(self.next_update, self.data.time)

    def _control(self, data: Any, dt: float) -> None:
        p = self.params
        speed = approach(self.speed, min(max(self.target[0], p.min_velocity), p.max_velocity),
                         dt, p.min_acceleration, p.max_acceleration)
        self.speed = speed
        turn = self.target[1]
        limit_radius = p.wheel_base / math.sin(p.steering_limit)
        if abs(turn) < 0.001:
            radius = 1e9
        elif abs(speed) > 0:
            radius = speed / turn
            if 0 <= radius < limit_radius:
                radius = limit_radius
            elif -limit_radius < radius <= 0:
                radius = -limit_radius
        else:
            radius = math.copysign(limit_radius, turn)
        half = p.kingpin_width / 2
        left_angle = math.atan(p.wheel_base / (radius - half))
        right_angle = math.atan(p.wheel_base / (radius + half))
        phi = math.atan(p.wheel_base / radius)
        ratio = p.wheel_separation * math.tan(phi) / (2 * p.wheel_base)
        right, left = (speed * (1 + ratio) / p.wheel_radius,
                       speed * (1 - ratio) / p.wheel_radius)
        ctrl, qpos = data.ctrl, data.qpos
        if not p.steering_only:
            for joint in p.left_joint:
                ctrl[self.ids[joint][1]] = left
            for joint in p.right_joint:
                ctrl[self.ids[joint][1]] = right
        for joint, angle in zip(self.steering, (left_angle, right_angle), strict=True):
            position, actuator = self.ids[joint]
            ctrl[actuator] = p.steer_p_gain * (angle - qpos[position])

    def _integrate(self, data: Any) -> None:
        p = self.params
        travelled = sum(data.qpos[self.ids[j][0]] for j in self.wheels) / len(self.wheels) * \
            p.wheel_radius
        now = data.time
        if self.previous is None:
            self.previous, self.last_time = travelled, now
            return
        distance = travelled - self.previous
        self.previous = travelled
        left, right = (data.qpos[self.ids[j][0]] for j in self.steering)
        cot = (1 / math.tan(left) + 1 / math.tan(right)) / 2 if left and right else 0.0
        turn = distance / (p.wheel_base * cot) if cot else 0.0
        heading = self.heading + turn / 2
        self.x += distance * math.cos(heading)
        self.y += distance * math.sin(heading)
        self.heading = math.atan2(math.sin(self.heading + turn), math.cos(self.heading + turn))
        dt = now - (self.last_time or now)
        self.last_time = now
        if dt > 0:
            self.linear, self.angular = distance / dt, turn / dt

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        dt = now - self.last_time if self.last_time is not None else 0.0
        self._control(data, dt)
        self._integrate(data)
        if self.odometry.due(now):
            self._publish(now)
        self.next_update = min(now + CONTROL_PERIOD, self.odometry.next)

    def _publish(self, now: float) -> None:
        publish_odometry(self, now, self.x, self.y, self.heading, self.linear, self.angular)

    def close(self) -> None:
        for item in (self.cmd_sub, self.odom_pub, self.tf_pub):
            item.destroy()
