"""Joint controllers for arms: a position servo and a velocity servo per joint.

JointPositionController (Gazebo's gz-sim-joint-position-controller-system), with gz-sim's
parameters and defaults: `joint_name`, `joint_index` (0), the PID `p_gain` (1), `i_gain`
(0.1), `d_gain` (0.01), `i_max` / `i_min` (±1: the integral term's bounds), `cmd_max` /
`cmd_min` (±1000: the force's), `cmd_offset` (0), `initial_position`, and
`use_velocity_commands` (move the joint by velocity, at most `cmd_max` per second, instead of
by force). Topics as gz-sim makes them: `<topic>` as given (relative names are from the
root), `<sub_topic>` under `/model/<name>/`, else `/model/<name>/joint/<joint>/<index>/cmd_pos`.
The P and D terms are a MuJoCo position servo (stable at any gain: integrated implicitly);
the I term and the offset are added to it every I_PERIOD of sim time. (launcher's own short
names, `joint_position_controller` and `joint_velocity_controller`, keep relative `<topic>`s
under the model.)

JointVelocityController (gz-sim-joint-controller-system): `joint_name`, `initial_velocity`,
velocity mode (the joint held at the commanded speed) or `use_force_commands` (a PID on the
speed error: `p_gain`, `i_gain`, `i_max`, `i_min`, `cmd_max`, `cmd_min`, `cmd_offset`), and the
same topic rules (default `/model/<name>/joint/<joint>/cmd_vel`). Each adds one MuJoCo
actuator on its joint; a NaN command is ignored with one warning.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.records import dataclass
from launcher.schema import Kind, attr
from launcher.sim import schedule
from launcher.sim.plugins import Plugin, PluginError


@dataclass
class Parameters:
    """gz-sim's joint position and joint (velocity) controllers' parameters."""

    joint_name: str = attr(Kind.TEXT, "", required=True)
    joint_index: int = attr(Kind.INT, 0, minimum=0)
    topic: str = attr(Kind.TEXT, "")
    sub_topic: str = attr(Kind.TEXT, "")
    p_gain: float | None = attr(Kind.FLOAT, None, minimum=0.0)
    d_gain: float | None = attr(Kind.FLOAT, None, minimum=0.0)
    i_gain: float | None = attr(Kind.FLOAT, None)
    i_max: float = attr(Kind.FLOAT, 1.0)
    i_min: float = attr(Kind.FLOAT, -1.0)
    cmd_max: float | None = attr(Kind.FLOAT, None)
    cmd_min: float | None = attr(Kind.FLOAT, None)
    cmd_offset: float = attr(Kind.FLOAT, 0.0)
    use_velocity_commands: bool = attr(Kind.BOOL, False)
    use_force_commands: bool = attr(Kind.BOOL, False)
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
        low, high = self.limits()
        if math.isfinite(low) or math.isfinite(high):
            actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
            actuator.forcerange = [low if math.isfinite(low) else -1e9,
                                   high if math.isfinite(high) else 1e9]
        self.command = self.initial()
        self.integral = 0.0
        self.last_time: float | None = None

    def configure(self, actuator: Any) -> None:
        raise NotImplementedError

    def initial(self) -> float:
        raise NotImplementedError

    def limits(self) -> tuple[float, float]:
        """The actuator's force range (infinite: none)."""
        raise NotImplementedError

    def bounds(self, default: float) -> tuple[float, float]:
        """cmd_min and cmd_max, ±`default` where not given."""
        p = self.params
        return (p.cmd_min if p.cmd_min is not None else -default,
                p.cmd_max if p.cmd_max is not None else default)

    def command_topic(self) -> str:
        """gz-sim's rule: <topic> as given, <sub_topic> under the model, else the default."""
        p = self.params
        if self.config.filename in ("joint_position_controller", "joint_velocity_controller"):
            # launcher's own short names: relative topics under the model, as before
            return self.topic(p.topic or None, self.default_topic.format(
                joint=self.joint, index=p.joint_index))
        if p.topic:
            return "/" + p.topic.lstrip("/")
        if p.sub_topic:
            return f"/model/{self.entity.name}/{p.sub_topic.lstrip('/')}"
        return self.topic(None, self.default_topic.format(joint=self.joint,
                                                          index=p.joint_index))

    def load(self) -> None:
        topic = self.command_topic()
        self.subscription = self.sim.transport.subscribe("mujoco_sim/msg/Double", topic,
                                                         self.on_command)

    def bind(self, model: Any, data: Any) -> None:
        self.index = model.actuator(f"{self.entity.name}/{self.actuator_name}").id
        data.ctrl[self.index] = self.command
        self.data = data
        self.dof = int(model.joint(f"{self.entity.name}/{self.joint}").dofadr[0])

    def gain_from_inertia(self, model: Any, fallback: float) -> float:
        """A velocity servo's gain that settles the joint in about SERVO_TIME (`fallback` for
        a joint with no inertia), set on its actuator."""
        gain = float(model.dof_M0[self.dof]) / SERVO_TIME or fallback
        model.actuator_gainprm[self.index, 0] = gain
        model.actuator_biasprm[self.index, 2] = -gain
        return gain

    def _apply(self, data: Any) -> None:
        """The servo's target: the command, and what the kind adds to it."""
        data.ctrl[self.index] = self.command

    def integrate(self, now: float, error: float) -> None:
        """The integral term over the sim time since the last update."""
        dt = now - self.last_time if self.last_time is not None else 0.0
        self.last_time = now
        self.integral += error * dt

    def integral_and_offset(self, gain: float) -> float:
        """The I term within [i_min, i_max] and the offset, as a shift of a servo of `gain`'s
        target."""
        p = self.params
        extra = min(max(self.ki * self.integral, p.i_min), p.i_max) + p.cmd_offset
        return extra / gain if gain else 0.0

    def on_command(self, message: Any) -> None:
        if not math.isfinite(message.data):
            self.warn_once("nan", f"entity '{self.entity.name}': ignoring a {self.kind} command "
                           f"for '{self.joint}' that is not finite ({message.data}); warned "
                           "once")
            return
        self.command = message.data
        self._apply(self.data)

    def reset(self) -> None:
        self.integral, self.last_time = 0.0, None
        self.command = self.initial()
        if hasattr(self, "data"):
            self.data.ctrl[self.index] = self.command

    def close(self) -> None:
        self.subscription.destroy()


I_PERIOD = 0.002  # s of sim time between updates of the integral term


class JointPositionController(_JointServo):
    kind = "position"
    default_topic = "joint/{joint}/{index}/cmd_pos"

    def configure(self, actuator: Any) -> None:
        p = self.params
        self.kp = 1.0 if p.p_gain is None else p.p_gain
        self.ki = 0.1 if p.i_gain is None else p.i_gain
        kd = 0.01 if p.d_gain is None else p.d_gain
        self.by_velocity = p.use_velocity_commands
        if self.by_velocity:  # gz: a velocity of −error/dt, at most cmd_max
            actuator.set_to_velocity(kv=1.0)  # the gain is set from the joint at bind
        else:
            actuator.set_to_position(kp=self.kp, kv=kd)

    def limits(self) -> tuple[float, float]:
        if self.params.use_velocity_commands:  # cmd_max bounds the speed, not the force
            return -math.inf, math.inf
        return self.bounds(1000.0)

    def initial(self) -> float:
        return self.params.initial_position

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        self.qpos = int(model.joint(f"{self.entity.name}/{self.joint}").qposadr[0])
        if self.by_velocity:
            self.gain_from_inertia(model, 200.0)
        self._apply(data)

    def _apply(self, data: Any) -> None:
        """The servo's target, with the integral term and the offset folded into it."""
        if self.by_velocity:
            error = data.qpos[self.qpos] - self.command
            step = self.model_timestep
            speed = -error / step
            top = self.params.cmd_max
            if top is not None and abs(error) > top * step:
                speed = math.copysign(top, speed)
            data.ctrl[self.index] = speed
            return
        data.ctrl[self.index] = self.command + self.integral_and_offset(self.kp)

    def post_step(self, model: Any, data: Any) -> None:
        self.model_timestep = model.opt.timestep
        now = data.time
        if self.by_velocity:
            self._apply(data)
            self.next_update = now  # every step, as gz's velocity mode
            return
        if self.ki:
            self.integrate(now, self.command - data.qpos[self.qpos])
            self._apply(data)
        self.next_update = schedule.following(self.next_update, now, I_PERIOD) if self.ki \
            else math.inf

    model_timestep = 0.001


class JointVelocityController(_JointServo):
    """gz-sim's JointController. Velocity mode (the default under Gazebo's names): the joint
    is held at the commanded speed (gz: JointVelocityCmd), by a servo whose gain comes from the
    joint's inertia, so it settles in about SERVO_TIME. Force mode (`use_force_commands`): a
    PID on the speed error, `p_gain` (1), `i_gain` (0) within `i_min`/`i_max`, `cmd_max` /
    `cmd_min` (±1000) bounding the force, `cmd_offset`. launcher's own short name keeps a
    servo of gain `p_gain`."""

    kind = "velocity"
    default_topic = "joint/{joint}/cmd_vel"

    def configure(self, actuator: Any) -> None:
        p = self.params
        self.short_name = self.config.filename == "joint_velocity_controller"
        self.force_mode = p.use_force_commands and not self.short_name
        self.kv = 1.0 if p.p_gain is None else p.p_gain
        self.ki = (p.i_gain or 0.0) if self.force_mode else 0.0
        self.from_inertia = not (self.force_mode or self.short_name)
        actuator.set_to_velocity(kv=self.kv)

    def limits(self) -> tuple[float, float]:
        return self.bounds(1000.0 if self.force_mode else math.inf)

    def initial(self) -> float:
        return self.params.initial_velocity

    def bind(self, model: Any, data: Any) -> None:
        super().bind(model, data)
        if self.from_inertia:
            self.kv = self.gain_from_inertia(model, self.kv)
        self._apply(data)

    def _apply(self, data: Any) -> None:
        extra = self.integral_and_offset(self.kv) if self.force_mode else 0.0
        data.ctrl[self.index] = self.command + extra

    def post_step(self, model: Any, data: Any) -> None:
        if not (self.ki or self.params.cmd_offset) or not self.force_mode:
            self.next_update = math.inf
            return
        now = data.time
        self.integrate(now, self.command - data.qvel[self.dof])
        self._apply(data)
        self.next_update = schedule.following(self.next_update, now, I_PERIOD)


SERVO_TIME = 0.005  # s: how fast a velocity servo with a gain from the joint's inertia settles
