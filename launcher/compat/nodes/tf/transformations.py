"""tf.transformations' Euler angle and quaternion helpers (static x-y-z, `sxyz`, the axes ROS
code uses), quaternions as [x, y, z, w]."""

from __future__ import annotations

import math
from collections.abc import Sequence


def quaternion_from_euler(ai: float, aj: float, ak: float, axes: str = "sxyz") -> list[float]:
    if axes != "sxyz":
        raise ValueError(f"axes '{axes}': only 'sxyz' (roll, pitch, yaw) is provided")
    cr, sr = math.cos(ai / 2), math.sin(ai / 2)
    cp, sp = math.cos(aj / 2), math.sin(aj / 2)
    cy, sy = math.cos(ak / 2), math.sin(ak / 2)
    return [sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy]


def euler_from_quaternion(quaternion: Sequence[float], axes: str = "sxyz"
                          ) -> tuple[float, float, float]:
    if axes != "sxyz":
        raise ValueError(f"axes '{axes}': only 'sxyz' (roll, pitch, yaw) is provided")
    x, y, z, w = quaternion
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return roll, pitch, yaw


def quaternion_multiply(q1: Sequence[float], q0: Sequence[float]) -> list[float]:
    x1, y1, z1, w1 = q1
    x0, y0, z0, w0 = q0
    return [w1 * x0 + x1 * w0 + y1 * z0 - z1 * y0, w1 * y0 - x1 * z0 + y1 * w0 + z1 * x0,
            w1 * z0 + x1 * y0 - y1 * x0 + z1 * w0, w1 * w0 - x1 * x0 - y1 * y0 - z1 * z0]


def quaternion_inverse(quaternion: Sequence[float]) -> list[float]:
    x, y, z, w = quaternion
    norm = x * x + y * y + z * z + w * w
    return [-x / norm, -y / norm, -z / norm, w / norm]
