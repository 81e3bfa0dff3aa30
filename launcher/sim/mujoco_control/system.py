"""mujoco_ros2_control/MujocoSystemInterface: a `<ros2_control>` block over the MJCF's own
actuators, as mujoco_ros2_control drives them.

Each joint of the block is moved by the actuators of its name (an actuator on the joint of that
name, or named so), or by a `<transmission>`'s. Its command interfaces follow the actuators'
kinds: `position` drives a position servo directly and a velocity servo, motor or custom
actuator through a position PID; `velocity` a velocity servo directly and a motor or custom
actuator through a velocity PID; `effort` (`torque`, `force`) a motor or custom actuator. A
combination the actuator cannot follow is refused at start, naming the joint. PIDs come from
the `pids_config_file` (`pid_gains.position.<joint>`, `pid_gains.velocity.<joint>`).

States: position, velocity and effort (`torque` and `force` are effort) of each joint, read from
qpos, qvel and the actuator force at its DOF; sensors of the block with a `mujoco_type` (`fts`,
`imu`, `pose`, `magnetometer`) from the MJCF's sensors named `<mujoco_sensor_name><suffix>`.
At start every joint holds where it is (its state interfaces' `initial_value`, else the
model's, or a keyframe's); a claimed command interface switches its actuators' mode.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco

from launcher.control.description import Hardware
from launcher.control.resources import Component
from launcher.errors import LaunchError, did_you_mean
from launcher.sim.mujoco_control.actuators import (
    PASSIVE,
    POSITION,
    VELOCITY,
    Actuator,
    Pid,
    actuators_of,
)
from launcher.sim.mujoco_control.transmissions import Coupling

EFFORTS = ("effort", "torque", "force")
SENSOR_PARTS = {  # mujoco_type: (interface prefix, hardware param of the suffix, default)
    "fts": (("force", "force_mjcf_suffix", "_force", 3, -1.0),
            ("torque", "torque_mjcf_suffix", "_torque", 3, -1.0)),
    "imu": (("orientation", "orientation_mjcf_suffix", "_quat", 4, 1.0),
            ("angular_velocity", "angular_velocity_mjcf_suffix", "_gyro", 3, 1.0),
            ("linear_acceleration", "linear_acceleration_mjcf_suffix", "_accel", 3, 1.0)),
    "pose": (("position", "position_mjcf_suffix", "_pos", 3, 1.0),
             ("orientation", "orientation_mjcf_suffix", "_quat", 4, 1.0)),
    "magnetometer": (("magnetic_field", None, "", 3, 1.0),),
}


def _kind(interface: str) -> str:
    return "effort" if interface in EFFORTS else interface


class MujocoSystem(Component):
    def __init__(self, info: Hardware, model: Any, data: Any, pids: dict[str, dict[str, Pid]],
                 log: Any, initial: bool = True) -> None:
        """`initial`: place the joints at their state interfaces' initial values (else the
        model starts where it is: a keyframe, a saved state)."""
        super().__init__(info)
        self.initial = initial
        self.model, self.data, self.log = model, data, log
        self.actuators = actuators_of(model, info.where)
        for actuator in self.actuators:
            actuator.pids = {mode: gains[actuator.joint] for mode, gains in pids.items()
                             if actuator.joint in gains and actuator.kind != PASSIVE
                             and actuator.qpos >= 0}  # (a PID needs the joint's state)
        self.couplings = [Coupling(t) for t in info.transmissions]
        self.by_joint: dict[str, list[Actuator]] = {}
        for joint in info.joints:
            self.by_joint[joint.name] = self._actuators_of(joint.name)
        self._check_commands()
        self.rows = [(j.name, self.by_joint[j.name], *(self.states.get(f"{j.name}/{k}")
                                                        for k in ("position", "velocity")),
                      [self.states[f"{j.name}/{k}"] for k in EFFORTS
                       if f"{j.name}/{k}" in self.states],
                      {_kind(i.name): self.commands[f"{j.name}/{i.name}"]
                       for i in j.command_interfaces})
                     for j in info.joints]
        self.mimics = [(j.name, j.mimic) for j in info.joints if j.mimic]
        self.commands_of = {row[0]: row[5] for row in self.rows}
        # each coupling with its actuators (None where the model lacks one), found once
        self.coupled = [(c, [next((a for a in self.actuators if (a.joint == n or a.name == n)
                                   and a.kind != PASSIVE), None) for n in c.actuator_names])
                        for c in self.couplings]
        self.sensor_rows = self._sensors()
        self.hold()

    # --- start ----------------------------------------------------------------------------
    def _actuators_of(self, joint: str) -> list[Actuator]:
        for coupling in self.couplings:
            if joint in coupling.joint_names:
                names = coupling.actuator_names
                return [a for a in self.actuators
                        if (a.joint in names or a.name in names) and a.kind != PASSIVE]
        driving = [a for a in self.actuators if a.joint == joint and a.kind != PASSIVE]
        if driving:
            return driving
        return [a for a in self.actuators if a.joint == joint]  # passive: read only

    def _check_commands(self) -> None:
        joints = [a.joint for a in self.actuators]
        for joint in self.info.joints:
            actuators = self.by_joint[joint.name]
            in_coupling = any(joint.name in c.joint_names for c in self.couplings)
            if not actuators and not in_coupling:
                raise LaunchError(
                    f"{self.info.where}: joint '{joint.name}' of <ros2_control "
                    f"name=\"{self.info.name}\"> is not a joint of the MuJoCo model"
                    f"{did_you_mean(joint.name, joints)} (its joints: {', '.join(joints)})")
            if not in_coupling:
                self._say_stateless(joint.name, actuators)
            if joint.mimic or not joint.command_interfaces:
                continue
            driving = [a for a in actuators if a.kind != PASSIVE]
            if not driving:
                raise LaunchError(
                    f"{self.info.where}: joint '{joint.name}' has command interfaces but no "
                    f"actuator of the MuJoCo model drives it (add one on the joint, or named "
                    f"as it)")
            for interface in joint.command_interfaces:
                kind = _kind(interface.name)
                if kind not in (POSITION, VELOCITY, "effort"):
                    raise LaunchError(f"{self.info.where}: joint '{joint.name}': command "
                                      f"interface '{interface.name}' is not one "
                                      f"mujoco_ros2_control drives (position, velocity, "
                                      f"effort)")
                for actuator in driving:
                    if kind not in actuator.modes():
                        need = {POSITION: "a position actuator, or a position PID in "
                                          "pids_config_file",
                                VELOCITY: "a velocity actuator, or a velocity PID in "
                                          "pids_config_file",
                                "effort": "a motor (or general) actuator"}[kind]
                        raise LaunchError(
                            f"{self.info.where}: joint '{joint.name}': its '{interface.name}' "
                            f"command interface needs {need}; actuator '{actuator.name}' is a "
                            f"{actuator.kind} actuator")

    def _say_stateless(self, joint: str, actuators: list[Actuator]) -> None:
        """A site actuator named as a joint the model lacks still pushes, but nothing gives
        the joint's states: said, since they stay 0."""
        stateless = [a.name for a in actuators if a.qpos < 0]
        if stateless:
            self.log.warning(f"{self.info.where}: joint '{joint}': actuator '{stateless[0]}' "
                             f"pushes on a site and the MuJoCo model has no joint '{joint}' "
                             f"to read its state from (a site actuator drives the joint of "
                             f"its own name); its states stay 0")

    def _sensors(self) -> list[tuple[Any, int, int, float]]:
        """(state handle, sensordata index, …) for each sensor interface with a mujoco_type."""
        model, rows = self.model, []
        names = [model.sensor(i).name for i in range(model.nsensor)]
        for sensor in self.info.sensors:
            kind = sensor.params.get("mujoco_type")
            if not kind:
                continue
            parts = SENSOR_PARTS.get(kind)
            if parts is None:
                raise LaunchError(f"{self.info.where}: sensor '{sensor.name}': mujoco_type "
                                  f"'{kind}' is not one of {', '.join(SENSOR_PARTS)}"
                                  f"{did_you_mean(kind, SENSOR_PARTS)}")
            base = sensor.params.get("mujoco_sensor_name", sensor.name)
            for prefix, param, default, size, sign in parts:
                mjcf = base + (self.info.params.get(param, default) if param else default)
                index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SENSOR, mjcf)
                if index < 0:
                    raise LaunchError(f"{self.info.where}: sensor '{sensor.name}' "
                                      f"({kind}) reads the MJCF sensor '{mjcf}', which the "
                                      f"model does not have{did_you_mean(mjcf, names)}")
                address = int(model.sensor_adr[index])
                axes = ("w", "x", "y", "z") if size == 4 else ("x", "y", "z")
                for offset, axis in enumerate(axes):
                    handle = self.states.get(f"{sensor.name}/{prefix}.{axis}")
                    if handle is not None:
                        rows.append((handle, address + offset, sign))
        return rows

    def hold(self) -> None:
        """Every joint at its initial value (a state interface's `initial_value`), its
        commands at its state and its actuators in their first mode: what the robot starts
        and resets to."""
        data = self.data
        for joint in self.info.joints:
            initial = next((i.initial_value for i in joint.state_interfaces
                            if i.name == POSITION and i.initial_value is not None), None)
            actuators = self.by_joint[joint.name]
            if self.initial and initial is not None and not any(joint.name in c.joint_names
                                               for c in self.couplings):
                for actuator in actuators:
                    if actuator.qpos >= 0:
                        data.qpos[actuator.qpos] = initial
                        data.qvel[actuator.dof] = 0.0
        mujoco.mj_forward(self.model, data)
        self.sync_commands()

    def sync_commands(self) -> None:
        """Commands to the present state, PIDs reset, each actuator in its first mode."""
        for actuator in self.actuators:
            modes = actuator.modes()
            actuator.mode = modes[0] if modes and actuator.kind != PASSIVE else ""
            for pid in actuator.pids.values():
                pid.reset()
        self.read(0.0, 0.0)
        for row in self.rows:
            commands = row[5]
            if POSITION in commands and row[2] is not None:
                commands[POSITION].value = row[2].value
            for kind in (VELOCITY, "effort"):
                if kind in commands:
                    commands[kind].value = 0.0
        for actuator in self.actuators:
            actuator.command = {POSITION: actuator.position, VELOCITY: 0.0, "effort": 0.0}
            if actuator.index >= 0 and actuator.kind == POSITION:
                self.data.ctrl[actuator.index] = actuator.position

    def bind(self, model: Any, data: Any) -> None:
        self.model, self.data = model, data

    # --- the cycle ------------------------------------------------------------------------
    def read(self, time: float, period: float) -> None:
        qpos, qvel, force = self.data.qpos, self.data.qvel, self.data.qfrc_actuator
        for actuator in self.actuators:
            if actuator.qpos >= 0:
                actuator.position = float(qpos[actuator.qpos])
                actuator.velocity = float(qvel[actuator.dof])
                actuator.effort = float(force[actuator.dof])
        joint_values: dict[str, list[float]] = {}
        for coupling, found in self.coupled:
            if None in found:
                continue
            values = coupling.to_joints([(a.position, a.velocity, a.effort) for a in found])
            joint_values.update(zip(coupling.joint_names, values, strict=True))
        for name, actuators, position, velocity, efforts, _ in self.rows:
            values = joint_values.get(name)
            if values is None:
                if not actuators:
                    continue
                a = actuators[0]
                values = [a.position, a.velocity, a.effort]
            if position is not None:
                position.value = values[0]
            if velocity is not None:
                velocity.value = values[1]
            for handle in efforts:
                handle.value = values[2]
        sensordata = self.data.sensordata
        for handle, index, sign in self.sensor_rows:
            handle.value = sign * float(sensordata[index])

    def write(self, time: float, period: float) -> None:
        commands = self.commands_of
        for name, (leader, multiplier, _offset) in self.mimics:
            mine, theirs = commands.get(name, {}), commands.get(leader, {})
            for kind, handle in mine.items():
                if kind in theirs:
                    handle.value = theirs[kind].value * multiplier
        coupled: set[str] = set()
        for coupling, found in self.coupled:
            if None in found:
                continue
            joints = [tuple(_value(commands.get(n, {}), k) for k in (POSITION, VELOCITY,
                                                                     "effort"))
                      for n in coupling.joint_names]
            for actuator, values in zip(found, coupling.to_actuators(joints), strict=True):
                actuator.command = dict(zip((POSITION, VELOCITY, "effort"), values,
                                            strict=True))
            coupled.update(coupling.joint_names)
        for name, actuators, *_rest, mine in self.rows:
            if name in coupled:
                continue
            for actuator in actuators:
                for kind, handle in mine.items():
                    actuator.command[kind] = handle.value
        ctrl, qpos, qvel = self.data.ctrl, self.data.qpos, self.data.qvel
        for actuator in self.actuators:
            if actuator.index < 0 or not actuator.mode:
                continue
            wanted = actuator.command.get(actuator.mode, math.nan)
            if not math.isfinite(wanted):
                continue
            pid = actuator.pids.get(actuator.mode) if actuator.kind != actuator.mode else None
            if actuator.mode == POSITION and pid is not None:
                value = pid.compute(wanted - qpos[actuator.qpos], period)
            elif actuator.mode == VELOCITY and pid is not None:
                value = pid.compute(wanted - qvel[actuator.dof], period)
            else:
                value = wanted
            ctrl[actuator.index] = value

    def switch_modes(self, start: list[str], stop: list[str]) -> None:
        """A claimed command interface drives its joint's actuators (the PID where the
        actuator's own kind is another); a released one leaves them undriven."""
        for names, on in ((stop, False), (start, True)):
            for name in names:
                joint, _, interface = name.rpartition("/")
                for actuator in self._driven_by(joint):
                    actuator.mode = _kind(interface) if on else ""
                    for pid in actuator.pids.values():
                        pid.reset()

    def _driven_by(self, joint: str) -> list[Actuator]:
        return [a for a in self.by_joint.get(joint, []) if a.kind != PASSIVE]


def _value(commands: dict[str, Any], kind: str) -> float:
    handle = commands.get(kind)
    return handle.value if handle is not None else 0.0
