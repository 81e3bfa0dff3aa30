"""Joint state publisher: positions, velocities and efforts of a model's joints.

Gazebo's gz-sim-joint-state-publisher-system parameters: `joint_name` (repeatable; default all
hinge and slide joints), `topic` (default `/world/<world>/model/<name>/joint_state`), and
`update_rate` (Hz of sim time, default 50). Names are published without the entity prefix,
as they are in the URDF. While the world is paused it goes on publishing, as gz-sim's does
(its PostUpdate runs paused), so a world opened paused already has its joints' state.
"""

from __future__ import annotations

from typing import Any

import mujoco

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim.plugins import PluginError
from launcher.sim.plugins.periodic import PeriodicPublisher

MOVING = (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)


@dataclass
class Parameters:
    """gz-sim-joint-state-publisher-system's parameters."""

    joint_name: list[str] = attr(Kind.NAMES)
    topic: str = attr(Kind.TEXT, "")
    update_rate: float = attr(Kind.FLOAT, 50.0, minimum=0.0)


class JointStatePublisher(PeriodicPublisher):
    declared = Parameters

    def prepare(self, spec: Any) -> None:
        available = self.joint_names(spec, MOVING)
        self.params = self.parameters(self.declared)
        self.joints = self.params.joint_name or available
        for joint in self.joints:
            if joint not in available:
                raise PluginError(f"{self.config.where}: plugin {self.label}: joint '{joint}' is "
                                  f"not a moving joint of the model (joints: "
                                  f"{', '.join(available) or 'none'})")
        self.rate = self.params.update_rate

    def load(self) -> None:
        default = f"/world/{self.sim.world_name}/model/{self.entity.name}/joint_state"
        self.publisher = self.sim.transport.publisher("mujoco_sim/msg/Model",
                                                      self.topic(self.params.topic, default))
        self.reset()

    def bind(self, model: Any, data: Any) -> None:
        ids = [model.joint(f"{self.entity.name}/{j}").id for j in self.joints]
        self.qpos = [int(model.jnt_qposadr[i]) for i in ids]
        self.dofs = [int(model.jnt_dofadr[i]) for i in ids]

    def measure(self, model: Any, data: Any) -> Any:
        return self.state(self.sim.transport, data.time, data)

    def paused(self, model: Any, data: Any) -> None:
        if self.publisher.get_subscription_count():
            self.publisher.publish(self.measure(model, data))

    def state(self, transport: Any, now: float, data: Any) -> Any:
        """The message of the joints' state now."""
        return transport.message(
            "mujoco_sim/msg/Model", header=transport.header(now, ""), name=self.entity.name,
            joint_name=self.joints, position=data.qpos[self.qpos],
            velocity=data.qvel[self.dofs], effort=data.qfrc_actuator[self.dofs])

    def close(self) -> None:
        self.publisher.destroy()
