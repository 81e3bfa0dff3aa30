"""Joint controllers for arms: a position servo and a velocity servo per joint.

JointPositionController (Gazebo's gz-sim-joint-position-controller-system): `joint_name`,
`p_gain` (1), `d_gain` (0.1), `cmd_max` / `cmd_min` (force limits), `initial_position`, `topic`
(default `joint/<joint>/0/cmd_pos`, under `/model/<name>/`), std Double commands in radians
(or metres). JointVelocityController (gz-sim-joint-controller-system): `joint_name`, `p_gain`
(velocity gain, 1), `cmd_max` / `cmd_min`, `initial_velocity`, `topic` (default
`joint/<joint>/cmd_vel`). Each adds one MuJoCo actuator on its joint; a NaN command is
ignored with one warning.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim.plugins import Plugin, PluginError


@dataclass
class Parameters:
    """gz-sim's joint position and joint (velocity) controllers' parameters."""

    joint_name: str = attr(Kind.TEXT, "", required=True)
    topic: str = attr(Kind.TEXT, "")
    p_gain: float = attr(Kind.FLOAT, 1.0, minimum=0.0)
    d_gain: float = attr(Kind.FLOAT, 0.1, minimum=0.0)
    i_gain: float = attr(Kind.FLOAT, 0.0)  # accepted; MuJoCo's servos have no integral term
    cmd_max: float = attr(Kind.FLOAT, math.inf)
    cmd_min: float = attr(Kind.FLOAT, -math.inf)
    initial_position: float = attr(Kind.FLOAT, 0.0)
    initial_velocity: float = attr(Kind.FLOAT, 0.0)


class _JointServo(Plugin):
    kind = ""
    default_topic = ""

    def prepare(self, spec: Any) -> None:
        self.params = self.parameters(Parameters)
        self.joint = self.params.joint_name
        joints = self.joint_names(spec)
        if self.joint not in joints:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <joint_name> "
                              f"'{self.joint}' is not in the model (joints: {', '.join(joints)})")
        self.actuator_name = f"{self.kind}_{self.joint}"
        actuator = spec.add_actuator(name=self.in_spec(self.actuator_name),
                                     target=self.in_spec(self.joint),
                                     trntype=mujoco.mjtTrn.mjTRN_JOINT)
        self.configure(actuator)
        low, high = self.params.cmd_min, self.params.cmd_max
        if math.isfinite(low) or math.isfinite(high):
            actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            actuator.forcerange = [low if math.isfinite(low) else -1e9,
                                   high if math.isfinite(high) else 1e9]
        self.command = self.initial()
        self._warned = False

    def configure(self, actuator: Any) -> None:
        raise NotImplementedError

    def initial(self) -> float:
        raise NotImplementedError

    def load(self) -> None:
        topic = self.topic(self.params.topic, self.default_topic.format(joint=self.joint))
        self.subscription = self.sim.transport.subscribe("mujoco_sim/msg/Double", topic,
                                                         self.on_command)

    def bind(self, model: Any, data: Any) -> None:
        self.index = model.actuator(f"{self.entity.name}/{self.actuator_name}").id
        data.ctrl[self.index] = self.command
        self.data = data

    def on_command(self, message: Any) -> None:
        if not math.isfinite(message.data):
            if not self._warned:
                self._warned = True
                self.sim.transport.logger.warning(
                    f"entity '{self.entity.name}': ignoring a {self.kind} command for "
                    f"'{self.joint}' that is not finite ({message.data}); warned once")
            return
        self.command = message.data
        self.data.ctrl[self.index] = message.data

    def reset(self) -> None:
        self.command = self.initial()
        if hasattr(self, "data"):
            self.data.ctrl[self.index] = self.command

    def close(self) -> None:
        self.subscription.destroy()


class JointPositionController(_JointServo):
    kind = "position"
    default_topic = "joint/{joint}/0/cmd_pos"

    def configure(self, actuator: Any) -> None:
        actuator.set_to_position(kp=self.params.p_gain, kv=self.params.d_gain)

    def initial(self) -> float:
        return self.params.initial_position


class JointVelocityController(_JointServo):
    kind = "velocity"
    default_topic = "joint/{joint}/cmd_vel"

    def configure(self, actuator: Any) -> None:
        actuator.set_to_velocity(kv=self.params.p_gain)

    def initial(self) -> float:
        return self.params.initial_velocity
