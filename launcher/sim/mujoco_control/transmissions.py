"""transmission_interface's simple and differential transmissions between ros2_control's
joints and the MJCF's actuators: positions (with the joints' offsets), velocities and efforts
each way, as transmission_interface computes them."""

from __future__ import annotations

from typing import Any

from launcher.control.description import Transmission

FIELDS = ("position", "velocity", "effort")


def _ordered(items: list[Any], prefix: str) -> list[Any]:
    """By role (`joint1`, `joint2`; `actuator1`, …) where roles are given, else as written."""
    if all(item[1].startswith(prefix) for item in items):
        return sorted(items, key=lambda item: item[1])
    return list(items)


class Coupling:
    """One `<transmission>`: `joints` and `actuators` are the objects it moves values
    between (each with position, velocity, effort and a `command` dict)."""

    def __init__(self, info: Transmission) -> None:
        self.info = info
        self.joint_names = [j[0] for j in _ordered(info.joints, "joint")]
        self.actuator_names = [a[0] for a in _ordered(info.actuators, "actuator")]
        joints = _ordered(info.joints, "joint")
        actuators = _ordered(info.actuators, "actuator")
        self.joint_reduction = [j[2] for j in joints]
        self.offset = [j[3] for j in joints]
        self.actuator_reduction = [a[2] for a in actuators]
        self.differential = info.plugin.endswith("DifferentialTransmission")

    def to_joints(self, actuator: list[tuple[float, float, float]]) -> list[list[float]]:
        """Actuators' (position, velocity, effort) → joints' [position, velocity, effort]."""
        jr, ar, off = self.joint_reduction, self.actuator_reduction, self.offset
        if not self.differential:
            r = jr[0] * ar[0]
            p, v, e = actuator[0]
            return [[p / r + off[0], v / r, e * r]]
        (p0, v0, e0), (p1, v1, e1) = actuator
        return [[(p0 / ar[0] + p1 / ar[1]) / (2 * jr[0]) + off[0],
                 (v0 / ar[0] + v1 / ar[1]) / (2 * jr[0]),
                 jr[0] * (e0 * ar[0] + e1 * ar[1])],
                [(p0 / ar[0] - p1 / ar[1]) / (2 * jr[1]) + off[1],
                 (v0 / ar[0] - v1 / ar[1]) / (2 * jr[1]),
                 jr[1] * (e0 * ar[0] - e1 * ar[1])]]

    def to_actuators(self, joint: list[tuple[float, float, float]]) -> list[list[float]]:
        """Joints' commanded (position, velocity, effort) → the actuators'."""
        jr, ar, off = self.joint_reduction, self.actuator_reduction, self.offset
        if not self.differential:
            r = jr[0] * ar[0]
            p, v, e = joint[0]
            return [[(p - off[0]) * r, v * r, e / r]]
        (p0, v0, e0), (p1, v1, e1) = joint
        q0, q1 = (p0 - off[0]) * jr[0], (p1 - off[1]) * jr[1]
        return [[(q0 + q1) * ar[0], (v0 * jr[0] + v1 * jr[1]) * ar[0],
                 (e0 / jr[0] + e1 / jr[1]) / (2 * ar[0])],
                [(q0 - q1) * ar[1], (v0 * jr[0] - v1 * jr[1]) * ar[1],
                 (e0 / jr[0] - e1 / jr[1]) / (2 * ar[1])]]
