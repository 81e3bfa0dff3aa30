"""Rigid poses and the maths to chain them, for world loading, spawning and moving entities
(no MuJoCo or numpy here: `create` uses it for its pose maths).

Quaternions are MuJoCo's order (w, x, y, z). Pure Python: a world has few poses, and loading
must not pay numpy's per-call overhead on each of them.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import NamedTuple

from launcher.errors import LaunchError

Vector = tuple[float, float, float]
Quat = tuple[float, float, float, float]


class PoseError(LaunchError):
    """A pose that cannot place anything (not finite, a zero quaternion)."""


class Pose(NamedTuple):  # a tuple: made many times while loading a world
    pos: Vector = (0.0, 0.0, 0.0)
    quat: Quat = (1.0, 0.0, 0.0, 0.0)

    def __mul__(self, other: Pose) -> Pose:  # type: ignore[override]
        """This pose then `other` expressed in it (parent * child)."""
        return Pose(_add(self.pos, rotate(self.quat, other.pos)),
                    _qmul(self.quat, other.quat))

    def inverse(self) -> Pose:
        conj = (self.quat[0], -self.quat[1], -self.quat[2], -self.quat[3])
        moved = rotate(conj, self.pos)
        return Pose((-moved[0], -moved[1], -moved[2]), conj)

    @property
    def is_identity(self) -> bool:
        return self == IDENTITY


IDENTITY = Pose()


def from_rpy(x: float, y: float, z: float, roll: float, pitch: float, yaw: float) -> Pose:
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return Pose((x, y, z), (cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
                            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy))


def rotate(quat: Quat, vector: Vector) -> Vector:
    w, x, y, z = quat
    vx, vy, vz = vector
    # v + 2w(q×v) + 2q×(q×v)
    cx, cy, cz = y * vz - z * vy, z * vx - x * vz, x * vy - y * vx
    return (vx + 2 * (w * cx + y * cz - z * cy), vy + 2 * (w * cy + z * cx - x * cz),
            vz + 2 * (w * cz + x * cy - y * cx))


def _qmul(a: Quat, b: Quat) -> Quat:
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw)


def _add(a: Vector, b: Vector) -> Vector:
    return a[0] + b[0], a[1] + b[1], a[2] + b[2]


def pose_from(values: Sequence[float]) -> tuple[list[float], list[float]]:
    """(x, y, z, roll, pitch, yaw) → position and MuJoCo quaternion (w, x, y, z)."""
    pose = from_rpy(*values)
    return list(pose.pos), list(pose.quat)


MAX_COORDINATE = 1e6  # metres from the world's origin: a pose past it is refused (MuJoCo
# resets a simulation whose positions pass 1e10, so `x: 1e300` would reset it every step)


def check_pose(position: Iterable[float], quat: Iterable[float]) -> None:
    position = list(position)
    values = [*position, *quat]
    if not all(math.isfinite(v) for v in values):
        raise PoseError(f"the pose must be finite, got {values}")
    if any(abs(v) > MAX_COORDINATE for v in position):
        raise PoseError(f"the position {position} is out of range: each coordinate must be "
                        f"within ±{MAX_COORDINATE:g} m of the world's origin")
    if sum(q * q for q in quat) < 1e-12:
        raise PoseError("the pose's orientation quaternion is zero")
