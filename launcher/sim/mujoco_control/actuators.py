"""The MJCF's actuators as mujoco_ros2_control sees them, and the PIDs it puts in front of some.

An actuator's kind comes from its bias, as mujoco_ros2_control reads it: no bias is a motor,
an affine bias with a position term a position servo, one with only a velocity term a velocity
servo, anything else custom. A moving joint no actuator drives (not free, not ball) is a
passive one: read, never written. An actuator that drives a tendon or a site is the joint of its
own name (the test robot's gripper: a tendon actuator named as the finger joint; a force on a
site of the slider named as the slider's joint).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import mujoco

from launcher.errors import LaunchError

POSITION, VELOCITY, MOTOR, CUSTOM, PASSIVE = "position", "velocity", "motor", "custom", "passive"
PID_FIELDS = ("p", "i", "d", "i_clamp_max", "i_clamp_min", "u_clamp_max", "u_clamp_min")


@dataclass
class Pid:
    """control_toolbox's PID: u = p·e + ∫i·e (clamped to i_clamp) + d·ė, clamped to u_clamp."""

    p: float = 0.0
    i: float = 0.0
    d: float = 0.0
    i_clamp_max: float = math.inf
    i_clamp_min: float = -math.inf
    u_clamp_max: float = math.inf
    u_clamp_min: float = -math.inf
    integral: float = 0.0
    last_error: float | None = None

    def compute(self, error: float, period: float) -> float:
        if period <= 0.0 or not math.isfinite(error):
            return 0.0
        self.integral = min(max(self.integral + self.i * error * period, self.i_clamp_min),
                            self.i_clamp_max)
        rate = 0.0 if self.last_error is None else (error - self.last_error) / period
        self.last_error = error
        u = self.p * error + self.integral + self.d * rate
        return min(max(u, self.u_clamp_min), self.u_clamp_max)

    def reset(self) -> None:
        self.integral, self.last_error = 0.0, None


@dataclass
class Actuator:
    """One MJCF actuator (`index` ≥ 0) or a passive joint (-1), with the joint it moves."""

    name: str
    index: int
    joint: str
    qpos: int
    dof: int
    kind: str
    pids: dict[str, Pid] = field(default_factory=dict)  # "position"/"velocity" → its PID
    mode: str = ""  # the command that drives it: position, velocity or effort ("" none)
    position: float = 0.0  # states
    velocity: float = 0.0
    effort: float = 0.0
    command: dict[str, float] = field(default_factory=lambda: {
        POSITION: math.nan, VELOCITY: math.nan, "effort": math.nan})

    def modes(self) -> list[str]:
        """The command interfaces this actuator can follow, as mujoco_ros2_control allows."""
        found = []
        if self.kind == POSITION or POSITION in self.pids:
            found.append(POSITION)
        if self.kind == VELOCITY or VELOCITY in self.pids:
            found.append(VELOCITY)
        if self.kind in (MOTOR, CUSTOM):
            found.append("effort")
        return found


def kind_of(model: Any, index: int) -> str:
    if model.actuator_biastype[index] == mujoco.mjtBias.mjBIAS_NONE:
        return MOTOR
    bias = model.actuator_biasprm[index]
    if model.actuator_biastype[index] == mujoco.mjtBias.mjBIAS_AFFINE:
        if bias[1] != 0:
            return POSITION
        if bias[2] != 0:
            return VELOCITY
    return CUSTOM


def actuators_of(model: Any, where: str) -> list[Actuator]:
    """Every actuator of the model, then every moving joint none drives (passive)."""
    found: list[Actuator] = []
    for index in range(model.nu):
        name = model.actuator(index).name or f"actuator {index}"
        joint, target = _moved_joint(model, index, name, where)
        if target < 0:  # a site actuator with no joint of its name: commands, no states
            found.append(Actuator(name, index, name, -1, -1, kind_of(model, index)))
            continue
        found.append(Actuator(name, index, joint, int(model.jnt_qposadr[target]),
                              int(model.jnt_dofadr[target]), kind_of(model, index)))
    driven = {a.qpos for a in found}
    moving = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
    for joint in range(model.njnt):
        if int(model.jnt_type[joint]) in moving and int(model.jnt_qposadr[joint]) not in driven:
            name = model.joint(joint).name
            if not name:
                raise LaunchError(f"{where}: joint {joint} of the MJCF has no name: every joint "
                                  f"but a free one needs one for mujoco_ros2_control")
            found.append(Actuator(name, -1, name, int(model.jnt_qposadr[joint]),
                                  int(model.jnt_dofadr[joint]), PASSIVE))
    return found


def _moved_joint(model: Any, index: int, name: str, where: str) -> tuple[str, int]:
    """(the name its state goes by, the joint it is read from; -1 for none), as
    mujoco_ros2_control registers it: a joint actuator by its joint; a tendon or site
    actuator by its own name, read from the joint of that name (a site's force moves whatever
    body it is on, so only the name says which joint is meant)."""
    transmission = int(model.actuator_trntype[index])
    if transmission == int(mujoco.mjtTrn.mjTRN_JOINT):
        target = int(model.actuator_trnid[index, 0])
        return model.joint(target).name, target
    if transmission not in (int(mujoco.mjtTrn.mjTRN_TENDON), int(mujoco.mjtTrn.mjTRN_SITE)):
        raise LaunchError(f"{where}: actuator '{name}': its transmission type "
                          f"({mujoco.mjtTrn(transmission).name}) is not one "
                          f"mujoco_ros2_control drives (joint, tendon or site)")
    target = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
    if target < 0 and transmission == int(mujoco.mjtTrn.mjTRN_TENDON):
        raise LaunchError(f"{where}: tendon actuator '{name}' has no joint of its name: "
                          f"mujoco_ros2_control reads a tendon actuator's state from "
                          f"the joint named as the actuator")
    return name, target


def pids_from(values: dict[str, Any]) -> dict[str, dict[str, Pid]]:
    """`pid_gains.<position|velocity>.<joint>.<field>` parameters as PIDs by mode and joint;
    a field that is not a PID's is refused, naming it."""
    found: dict[str, dict[str, Pid]] = {}
    for name, value in values.items():
        parts = name.split(".")
        if len(parts) != 4 or parts[0] != "pid_gains":
            continue
        _, mode, joint, gain = parts
        if mode not in (POSITION, VELOCITY):
            raise LaunchError(f"parameter '{name}': PIDs are for 'position' or 'velocity' "
                              f"commands, not '{mode}'")
        if gain not in PID_FIELDS:
            raise LaunchError(f"parameter '{name}': '{gain}' is not a PID gain "
                              f"({', '.join(PID_FIELDS)})")
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise LaunchError(f"parameter '{name}': expected a number, got {value!r}") from None
        setattr(found.setdefault(mode, {}).setdefault(joint, Pid()), gain, number)
    return found
