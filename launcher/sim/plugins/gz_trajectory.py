"""gz-sim's own JointTrajectoryController (gz-sim-joint-trajectory-controller-system):
gz.msgs.JointTrajectory on `<topic>` (`/model/<name>/joint_trajectory`), each point held from
its `time_from_start` until the next (gz-sim interpolates nothing: planners send dense
trajectories), its progress in (0, 1] as gz.msgs.Float on `<topic>_progress`.

Parameters, repeated per joint in `<joint_name>` order (default: every one-axis joint of the
model): `initial_position`, and `position_` / `velocity_` `p_gain`, `i_gain`, `d_gain`,
`i_min`, `i_max`, `cmd_min`, `cmd_max`, `cmd_offset` (all 0 by default: a gain of 0 is off;
limits apply only where min < max), and `use_header_start_time`. Each joint's force is the
position PID's plus the velocity PID's plus the point's effort, as gz-sim sums them. The P and
D terms and the velocity gain are one MuJoCo actuator per joint (integrated implicitly, so
stiff gains stay stable); targets change at the points' times, integral terms every
CONTROL_PERIOD.
A trajectory naming joints the controller does not have, or with NaN, is refused (one warning).
"""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.bus.wire import stamp_seconds
from launcher.sim import schedule
from launcher.sim.plugins import Plugin, PluginError

CONTROL_PERIOD = 0.001  # s of sim time between updates of the integral terms
GAINS = ("p_gain", "i_gain", "d_gain", "i_min", "i_max", "cmd_min", "cmd_max", "cmd_offset")
DEFAULTS = {"i_max": -1.0, "cmd_max": -1.0}


class JointTrajectoryController(Plugin):
    unknown_parameters = "ignore"  # the gains are read by name below

    def prepare(self, spec: Any) -> None:
        one_axis = (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)
        available = self.joint_names(spec, one_axis)
        self.joints = self.texts("joint_name") or available
        for joint in self.joints:
            if joint not in available:
                raise PluginError(f"{self.config.where}: plugin {self.label}: <joint_name> "
                                  f"'{joint}' is not a one-axis joint of the model (joints: "
                                  f"{', '.join(available)})")
        count = len(self.joints)
        self.gains = {f"{kind}_{name}": self._series(f"{kind}_{name}", count,
                                                     DEFAULTS.get(name, 0.0))
                      for kind in ("position", "velocity") for name in GAINS}
        self.initial = self._series("initial_position", count, 0.0)
        self.header_time = (self.text("use_header_start_time", "false") or "").lower() \
            in ("true", "1")
        for index, joint in enumerate(self.joints):
            actuator = spec.add_actuator(name=self.in_spec(f"trajectory_{joint}"),
                                         target=self.in_spec(joint),
                                         trntype=mujoco.mjtTrn.mjTRN_JOINT)
            kp = self.gains["position_p_gain"][index]
            kd = self.gains["position_d_gain"][index] + self.gains["velocity_p_gain"][index]
            actuator.gaintype = mujoco.mjtGain.mjGAIN_FIXED
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.gainprm[0] = 1.0
            actuator.biasprm[:3] = [0.0, -kp, -kd]
            low = self.gains["position_cmd_min"][index]
            high = self.gains["position_cmd_max"][index]
            if low < high:
                actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
                actuator.forcerange = [low, high]
        self.reset()

    def _series(self, tag: str, count: int, default: float) -> list[float]:
        values = []
        for text in self.texts(tag):
            try:
                values.append(float(text))
            except ValueError:
                raise PluginError(f"{self.config.where}: plugin {self.label}: <{tag}> '{text}' "
                                  f"is not a number") from None
        if len(values) > count:
            raise PluginError(f"{self.config.where}: plugin {self.label}: {len(values)} "
                              f"<{tag}> for {count} joints")
        return values + [default] * (count - len(values))

    def reset(self) -> None:
        self.target = [(p, 0.0, 0.0) for p in self.initial]  # (position, velocity, effort)
        self.points: list[tuple[float, list[tuple[float, float, float]]]] = []
        self.start = 0.0
        self.index = -1
        self.integral = [[0.0, 0.0] for _ in self.joints]
        self.last: float | None = None
        self.next_update = 0.0

    def load(self) -> None:
        name = self.entity.name
        topic = self.text("topic") or f"/model/{name}/joint_trajectory"
        topic = "/" + topic.lstrip("/")
        transport = self.sim.transport
        self.subscription = transport.subscribe("mujoco_sim/msg/JointTrajectory", topic,
                                                self.on_trajectory)
        self.progress_pub = transport.publisher("mujoco_sim/msg/Float", f"{topic}_progress")

    def bind(self, model: Any, data: Any) -> None:
        prefix = f"{self.entity.name}/"
        self.rows = []
        for joint in self.joints:
            index = model.joint(prefix + joint).id
            self.rows.append((int(model.jnt_qposadr[index]), int(model.jnt_dofadr[index]),
                              model.actuator(f"{prefix}trajectory_{joint}").id))
        self.data = data
        self._apply(data, 0.0)

    def on_trajectory(self, message: Any) -> None:
        names = list(message.joint_names)
        unknown = [n for n in names if n not in self.joints]
        values = [v for p in message.points for v in (*p.positions, *p.velocities, *p.effort)]
        if unknown or not all(math.isfinite(v) for v in values):
            why = f"joints {unknown} are not controlled" if unknown else "it holds NaN"
            self.sim.transport.logger.warning(
                f"entity '{self.entity.name}': joint trajectory refused: {why} "
                f"(joints: {', '.join(self.joints)})", once=True)
            return
        order = {name: i for i, name in enumerate(names)}
        points = []
        for point in message.points:
            target = []
            for k, joint in enumerate(self.joints):
                i = order.get(joint)
                previous = self.target[k]

                def pick(values: Any, fallback: float, i: int | None = i) -> float:
                    return float(values[i]) if i is not None and i < len(values) else fallback

                target.append((pick(point.positions, previous[0]),
                               pick(point.velocities, 0.0), pick(point.effort, 0.0)))
            stamp = point.time_from_start
            points.append((stamp_seconds(stamp), target))
        stamp = message.header.stamp
        now = self.data.time
        self.start = stamp_seconds(stamp) if self.header_time and \
            (stamp.sec or stamp.nanosec) else now
        self.points, self.index = points, -1
        self.next_update = now

    def _apply(self, data: Any, dt: float) -> None:
        gains = self.gains
        for k, (qpos, dof, actuator) in enumerate(self.rows):
            position, velocity, effort = self.target[k]
            kp, vp = gains["position_p_gain"][k], gains["velocity_p_gain"][k]
            extra = effort + gains["position_cmd_offset"][k] + gains["velocity_cmd_offset"][k]
            for j, kind, error in ((0, "position", position - data.qpos[qpos]),
                                   (1, "velocity", velocity - data.qvel[dof])):
                ki = gains[f"{kind}_i_gain"][k]
                if ki:
                    self.integral[k][j] += error * dt
                    term = ki * self.integral[k][j]
                    low, high = gains[f"{kind}_i_min"][k], gains[f"{kind}_i_max"][k]
                    extra += min(max(term, low), high) if low < high else term
            data.ctrl[actuator] = kp * position + vp * velocity + extra

    def post_step(self, model: Any, data: Any) -> None:
        now = data.time
        dt = now - self.last if self.last is not None else 0.0
        self.last = now
        if self.points:
            elapsed = now - self.start
            index = self.index
            while index + 1 < len(self.points) and \
                    schedule.is_due(elapsed, self.points[index + 1][0]):
                index += 1
            if index != self.index and index >= 0:
                self.index = index
                self.target = self.points[index][1]
                total = self.points[-1][0] or 1.0
                if self.progress_pub.get_subscription_count():
                    self.progress_pub.publish(self.sim.transport.message(
                        "mujoco_sim/msg/Float", data=min(self.points[index][0] / total, 1.0)))
            if self.index == len(self.points) - 1:
                self.points = []
        self._apply(data, dt)
        following = [math.inf]
        if self.points:  # the next point's time
            following.append(self.start + self.points[self.index + 1][0])
        if any(self.gains[f"{kind}_i_gain"][k] for kind in ("position", "velocity")
               for k in range(len(self.joints))):
            following.append(now + CONTROL_PERIOD)  # the integral terms
        self.next_update = min(following)

    def close(self) -> None:
        self.subscription.destroy()
        self.progress_pub.destroy()
