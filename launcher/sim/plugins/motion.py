"""Gazebo's systems that move a model directly: ApplyJointForce and VelocityControl.

ApplyJointForce (gz-sim-apply-joint-force-system): `joint_name`; gz.msgs.Double forces (or
torques) on `/model/<name>/joint/<joint>/cmd_force`, applied every step until the next one.

VelocityControl (gz-sim-velocity-control-system): the model's linear and angular velocity,
in its own frame, set every step from gz.msgs.Twist on `<topic>` (default
`/model/<name>/cmd_vel`), starting at `<initial_linear>` / `<initial_angular>`; each
`<link_name>` gets its own `/model/<name>/link/<link>/cmd_vel` (the link's velocity, set the
same way when the link has a free joint). A command holding NaN or an infinity is ignored
(one warning).
"""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim.plugins import Plugin, PluginError


@dataclass
class ForceParameters:
    joint_name: str = attr(Kind.TEXT, "", required=True)


class ApplyJointForce(Plugin):
    def prepare(self, spec: Any) -> None:
        self.joint = self.parameters(ForceParameters).joint_name
        joints = self.joint_names(spec)
        if self.joint not in joints:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <joint_name> "
                              f"'{self.joint}' is not in the model (joints: {', '.join(joints)})")
        spec.add_actuator(name=self.in_spec(f"force_{self.joint}"),
                          target=self.in_spec(self.joint), trntype=mujoco.mjtTrn.mjTRN_JOINT)
        self.force = 0.0

    def load(self) -> None:
        self.subscription = self.sim.transport.subscribe(
            "mujoco_sim/msg/Double", f"/model/{self.entity.name}/joint/{self.joint}/cmd_force",
            self.on_force)

    def bind(self, model: Any, data: Any) -> None:
        self.index = model.actuator(f"{self.entity.name}/force_{self.joint}").id
        self.data = data
        data.ctrl[self.index] = self.force

    def on_force(self, message: Any) -> None:
        if not math.isfinite(message.data):
            self.sim.transport.logger.warning(
                f"entity '{self.entity.name}': ignoring a force for '{self.joint}' that is not "
                f"finite ({message.data})", once=True)
            return
        self.force = message.data
        self.data.ctrl[self.index] = message.data

    def reset(self) -> None:
        self.force = 0.0
        if hasattr(self, "data"):
            self.data.ctrl[self.index] = 0.0

    def close(self) -> None:
        self.subscription.destroy()


@dataclass
class VelocityParameters:
    topic: str = attr(Kind.TEXT, "")
    initial_linear: str = attr(Kind.TEXT, "0 0 0")
    initial_angular: str = attr(Kind.TEXT, "0 0 0")
    link_name: list[str] = attr(Kind.NAMES)


class VelocityControl(Plugin):
    def prepare(self, spec: Any) -> None:
        p = self.params = self.parameters(VelocityParameters)
        self.initial = (self.three_numbers("initial_linear", p.initial_linear),
                        self.three_numbers("initial_angular", p.initial_angular))
        self.reset()

    def reset(self) -> None:
        self.target = (list(self.initial[0]), list(self.initial[1]))
        self.links: dict[str, tuple[list[float], list[float]] | None] = \
            {link: None for link in self.params.link_name}

    def load(self) -> None:
        name = self.entity.name
        transport = self.sim.transport
        topic = self.params.topic or f"/model/{name}/cmd_vel"
        self.subscriptions = [transport.subscribe("mujoco_sim/msg/Twist", topic, self.on_twist)]
        for link in self.params.link_name:
            self.subscriptions.append(transport.subscribe(
                "mujoco_sim/msg/Twist", f"/model/{name}/link/{link}/cmd_vel",
                lambda m, link=link: self._link(link, m)))

    def bind(self, model: Any, data: Any) -> None:
        self.model, self.data = model, data
        self.link_dofs = {}
        for link in self.params.link_name:
            body = model.body(f"{self.entity.name}/{link}").id
            joint = int(model.body_jntadr[body])
            free = joint >= 0 and model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE
            self.link_dofs[link] = (body, int(model.jnt_dofadr[joint]) if free else -1)

    def _read(self, message: Any) -> tuple[list[float], list[float]] | None:
        values = [message.linear.x, message.linear.y, message.linear.z,
                  message.angular.x, message.angular.y, message.angular.z]
        if not all(math.isfinite(v) for v in values):
            self.sim.transport.logger.warning(
                f"entity '{self.entity.name}': ignoring a velocity command with NaN or an "
                f"infinite value", once=True)
            return None
        return values[:3], values[3:]

    def on_twist(self, message: Any) -> None:
        found = self._read(message)
        if found is not None:
            self.target = found

    def _link(self, link: str, message: Any) -> None:
        found = self._read(message)
        if found is not None:
            self.links[link] = found

    def pre_step(self, model: Any, data: Any) -> None:
        entity = self.entity
        if entity.dof >= 0:
            _set_body_twist(data, entity.body, entity.dof, *self.target)
        for link, twist in self.links.items():
            body, dof = self.link_dofs[link]
            if twist is not None and dof >= 0:
                _set_body_twist(data, body, dof, *twist)

    def post_step(self, model: Any, data: Any) -> None:
        self.next_update = data.time  # every step: the velocity holds against the world

    def close(self) -> None:
        for subscription in self.subscriptions:
            subscription.destroy()


def _set_body_twist(data: Any, body: int, dof: int, linear: list[float],
                    angular: list[float]) -> None:
    """A free body's velocity from one in its own frame (gz's Linear/AngularVelocityCmd):
    MuJoCo's free joint takes the linear part in the world frame, the angular in the body's."""
    world = np.zeros(3)
    mujoco.mju_rotVecQuat(world, np.asarray(linear, dtype=float), data.xquat[body])
    data.qvel[dof:dof + 3] = world
    data.qvel[dof + 3:dof + 6] = angular
