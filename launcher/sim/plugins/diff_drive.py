"""Differential drive: cmd_vel → wheel velocity actuators; odometry from the wheel joints.

Parameters are Gazebo's (gz-sim-diff-drive-system): `left_joint`, `right_joint` (repeatable),
`wheel_separation` (1.0), `wheel_radius` (0.2), the command and odometry ones every drive
has (odometry.py): `odom_publish_frequency` (50 Hz), `topic` (`cmd_vel`), `odom_topic`
(`odometry`), `tf_topic` (`tf`), `frame_id` (`<name>/odom`), `child_frame_id`
(`<name>/<root link>`); and `max_linear_velocity`, `min_linear_velocity`,
`max_angular_velocity`, `min_angular_velocity`, `max_linear_acceleration`,
`min_linear_acceleration`, `max_angular_acceleration`, `min_angular_acceleration`. Relative
topics live under `/model/<name>/`. launcher's own: `cmd_vel_timeout` (seconds of sim time
without a command after which the wheels stop; 0 never stops them; default 0 under
Gazebo's names, where one command drives on as in Gazebo, and 0.5 s as `diff_drive`),
`wheel_response_time` (0.05 s: the wheel servo's gain is set from the robot's mass so a
speed change settles in about this time), `wheel_kv` (a fixed velocity gain in N·m·s/rad
instead) and `max_wheel_torque` (none; a limit on light wheels can make the servo overshoot).
"""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim.plugins import Plugin, PluginError
from launcher.sim.plugins.odometry import (
    OdometryParameters,
    OdometrySchedule,
    open_odometry,
    publish_odometry,
)

CONTROL_PERIOD = 0.01  # s of sim time between acceleration-limited control updates


@dataclass
class Parameters(OdometryParameters):
    """gz-sim-diff-drive-system's parameters, and launcher's own (see the module text)."""

    left_joint: list[str] = attr(Kind.NAMES, required=True)
    right_joint: list[str] = attr(Kind.NAMES, required=True)
    wheel_separation: float = attr(Kind.FLOAT, 1.0, above=0.0)
    wheel_radius: float = attr(Kind.FLOAT, 0.2, above=0.0)
    max_linear_velocity: float = attr(Kind.FLOAT, math.inf)
    min_linear_velocity: float = attr(Kind.FLOAT, -math.inf)
    max_angular_velocity: float = attr(Kind.FLOAT, math.inf)
    min_angular_velocity: float = attr(Kind.FLOAT, -math.inf)
    max_linear_acceleration: float = attr(Kind.FLOAT, math.inf)
    min_linear_acceleration: float = attr(Kind.FLOAT, -math.inf)
    max_angular_acceleration: float = attr(Kind.FLOAT, math.inf)
    min_angular_acceleration: float = attr(Kind.FLOAT, -math.inf)
    cmd_vel_timeout: float | None = attr(Kind.FLOAT, None, minimum=0.0)
    wheel_kv: float = attr(Kind.FLOAT, 0.0, minimum=0.0)
    wheel_response_time: float = attr(Kind.FLOAT, 0.05, minimum=1e-4)
    max_wheel_torque: float = attr(Kind.FLOAT, math.inf, minimum=0.0)


LIMITS = ("max_linear_velocity", "min_linear_velocity", "max_angular_velocity",
          "min_angular_velocity", "max_linear_acceleration", "min_linear_acceleration",
          "max_angular_acceleration", "min_angular_acceleration")


class DiffDrive(Plugin):
    def prepare(self, spec: Any) -> None:
        p = self.params = self.parameters(Parameters)
        self.left, self.right = p.left_joint, p.right_joint
        joints = self.joint_names(spec)
        twice = sorted({j for j in self.left + self.right if (self.left + self.right).count(j) > 1})
        if twice:
            raise PluginError(f"{self.config.where}: plugin {self.label}: joint "
                              f"'{twice[0]}' is given more than once")
        for joint in self.left + self.right:
            if joint not in joints:
                raise PluginError(f"{self.config.where}: plugin {self.label}: joint '{joint}' is "
                                  f"not in the model (joints: {', '.join(joints)})")
        self.separation, self.radius = p.wheel_separation, p.wheel_radius
        watchdog = 0.5 if self.config.filename == "diff_drive" else 0.0
        self.timeout = p.cmd_vel_timeout if p.cmd_vel_timeout is not None else watchdog
        self.kv, self.response, torque = p.wheel_kv, p.wheel_response_time, p.max_wheel_torque
        self.limits = {key: getattr(p, key) for key in LIMITS}
        for joint in self.left + self.right:
            actuator = spec.add_actuator(name=self.in_spec(f"diff_drive_{joint}"),
                                         target=self.in_spec(joint),
                                         trntype=mujoco.mjtTrn.mjTRN_JOINT)
            actuator.set_to_velocity(kv=self.kv or 1.0)  # 0: set from the mass in bind
            if math.isfinite(torque):
                actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
                actuator.forcerange = [-torque, torque]
        self.root = self.entity.root.removeprefix(f"{self.entity.name}/")
        self.reset()

    def load(self) -> None:
        open_odometry(self, self.params)
        self.cmd_sub = self.sim.transport.subscribe("mujoco_sim/msg/Twist",
                                                    self.topic(self.params.topic, "cmd_vel"),
                                                    self.on_cmd_vel)

    def bind(self, model: Any, data: Any) -> None:
        prefix = f"{self.entity.name}/"
        self.left_q = [int(model.jnt_qposadr[model.joint(prefix + j).id]) for j in self.left]
        self.right_q = [int(model.jnt_qposadr[model.joint(prefix + j).id]) for j in self.right]
        self.wheels_q = self.left_q + self.right_q
        self.left_a = [model.actuator(f"{prefix}diff_drive_{j}").id for j in self.left]
        self.right_a = [model.actuator(f"{prefix}diff_drive_{j}").id for j in self.right]
        if not self.kv:  # each wheel carries its share of the robot's mass
            mass = float(model.body_subtreemass[model.body(self.entity.root).id])
            wheels = len(self.left_a) + len(self.right_a)
            gain = mass / wheels * self.radius ** 2 / self.response
            for index in self.left_a + self.right_a:
                model.actuator_gainprm[index, 0] = gain
                model.actuator_biasprm[index, 2] = -gain
        self.data = data
        self._apply()

    def reset(self) -> None:
        self.x = self.y = self.theta = 0.0
        self.v = self.w = 0.0  # current (limited) command
        self.target = (0.0, 0.0)
        self.last_command = -math.inf
        self.odometry = OdometrySchedule(self.params.odom_publish_frequency)
        self.next_update = 0.0
        self.last_odom_time: float | None = None
        self.previous: tuple[float, float] | None = None
        self.linear = self.angular = 0.0  # measured speeds, from the wheels
        self._control_time: float | None = None

    # --- commands --------------------------------------------------------------------------
    def on_cmd_vel(self, message: Any) -> None:
        v, w = message.linear.x, message.angular.z
        if not (math.isfinite(v) and math.isfinite(w)):
            self.warn_once("nan", f"entity '{self.entity.name}': ignoring cmd_vel with a NaN "
                           f"or infinite value (linear.x={v}, angular.z={w}); warned once")
            return
        lim = self.limits
        self.target = (min(max(v, lim["min_linear_velocity"]), lim["max_linear_velocity"]),
                       min(max(w, lim["min_angular_velocity"]), lim["max_angular_velocity"]))
        self.last_command = self.data.time
        self._control(self.data.time)
        self.next_update = min(self.next_update, self.data.time)

    def _control(self, now: float) -> None:
        """Move the current command toward the target within the acceleration limits."""
        if self.timeout > 0 and now - self.last_command > self.timeout:
            self.target = (0.0, 0.0)
        dt = max(now - self._control_time, 0.0) if self._control_time is not None else 0.0
        self._control_time = now
        if (self.v, self.w) == self.target:
            return  # the wheels already have this command
        lim = self.limits
        self.v = approach(self.v, self.target[0], dt, lim["min_linear_acceleration"],
                          lim["max_linear_acceleration"])
        self.w = approach(self.w, self.target[1], dt, lim["min_angular_acceleration"],
                          lim["max_angular_acceleration"])
        self._apply()

    def _apply(self) -> None:
        half = self.w * self.separation / 2
        left, right = (self.v - half) / self.radius, (self.v + half) / self.radius
        ctrl = self.data.ctrl
        for index in self.left_a:
            ctrl[index] = left
        for index in self.right_a:
            ctrl[index] = right

    # --- stepping --------------------------------------------------------------------------
    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        self._control(now)
        self._integrate(data)
        if self.odometry.due(now):
            self._publish(now)
        following = [self.odometry.next]
        if (self.v, self.w) != self.target:
            following.append(now + CONTROL_PERIOD)
        if self.timeout > 0 and self.target != (0.0, 0.0):
            following.append(self.last_command + self.timeout)
        self.next_update = min(following)

    def _integrate(self, data: Any) -> None:
        values = data.qpos[self.wheels_q].tolist()  # left wheels, then right wheels
        count = len(self.left_q)
        left = sum(values[:count]) / count
        right = sum(values[count:]) / (len(values) - count)
        if self.previous is None:
            self.previous = (left, right)
            self.last_odom_time = data.time
            return
        d_left = (left - self.previous[0]) * self.radius
        d_right = (right - self.previous[1]) * self.radius
        self.previous = (left, right)
        distance, turn = (d_left + d_right) / 2, (d_right - d_left) / self.separation
        heading = self.theta + turn / 2
        self.x += distance * math.cos(heading)
        self.y += distance * math.sin(heading)
        self.theta = math.atan2(math.sin(self.theta + turn), math.cos(self.theta + turn))
        dt = data.time - (self.last_odom_time or data.time)
        self.last_odom_time = data.time
        if dt > 0:
            self.linear, self.angular = distance / dt, turn / dt

    def _publish(self, now: float) -> None:
        publish_odometry(self, now, self.x, self.y, self.theta, self.linear, self.angular)

    def close(self) -> None:
        for item in (self.odom_pub, self.tf_pub, self.cmd_sub):
            item.destroy()


def approach(current: float, target: float, dt: float, low: float, high: float) -> float:
    if math.isinf(low) and math.isinf(high):
        return target
    if dt <= 0:
        return current
    change = min(max(target - current, low * dt), high * dt)
    return current + change
