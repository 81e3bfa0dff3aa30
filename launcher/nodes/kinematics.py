"""A URDF's joint tree and its forward kinematics, every joint in one vectorised pass.

`Tree.parse(text)` checks the URDF (XML, one root, no loops, joints naming real links) and
keeps each joint's origin, axis, type and mimic. `Tree.transforms(positions)` gives, for the
moving joints, the parent → child transform (translation, quaternion x y z w) as numpy arrays,
as robot_state_publisher publishes them on /tf. Fixed joints' transforms are constant
(`Tree.fixed`). Floating and planar joints are skipped, as ROS's robot_state_publisher does.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

import numpy as np

from launcher.errors import LaunchError
from launcher.sim.urdf_tree import parse_robot, root_link

MOVING = ("revolute", "continuous", "prismatic")


@dataclass
class Joint:
    name: str
    kind: str
    parent: str
    child: str
    xyz: tuple[float, float, float]
    quat: tuple[float, float, float, float]  # x y z w
    axis: tuple[float, float, float]
    mimic: tuple[str, float, float] | None = None  # (master, multiplier, offset)


@dataclass
class Tree:
    name: str
    root: str
    joints: list[Joint]
    moving: list[Joint] = field(default_factory=list)
    fixed: list[Joint] = field(default_factory=list)

    @classmethod
    def parse(cls, text: str, label: str = "robot_description") -> Tree:
        if not text or not text.strip():
            raise LaunchError(f"{label} is empty: give the URDF (e.g. from $(command 'xacro "
                              "robot.xacro'))")
        robot = parse_robot(text, label)
        root = root_link(robot, text, label)
        joints = [_joint(element, label) for element in robot.findall("joint")]
        names = {j.name for j in joints}
        for joint in joints:
            if joint.mimic and joint.mimic[0] not in names:
                raise LaunchError(f"{label}: joint '{joint.name}' mimics '{joint.mimic[0]}', "
                                  "which is not a joint")
        tree = cls(robot.get("name", ""), root, joints)
        tree.moving = [j for j in joints if j.kind in MOVING]
        tree.fixed = [j for j in joints if j.kind == "fixed"]
        tree._arrays()
        return tree

    def _arrays(self) -> None:
        moving = self.moving
        self.index = {j.name: i for i, j in enumerate(moving)}
        self.origin_xyz = np.array([j.xyz for j in moving], dtype=float).reshape(-1, 3)
        self.origin_quat = np.array([j.quat for j in moving], dtype=float).reshape(-1, 4)
        axes = np.array([j.axis for j in moving], dtype=float).reshape(-1, 3)
        norms = np.linalg.norm(axes, axis=1, keepdims=True)
        self.axis = np.divide(axes, norms, out=np.zeros_like(axes), where=norms > 0)
        prismatic = np.array([j.kind == "prismatic" for j in moving], dtype=bool)
        # A revolute joint's rotation is origin ⊗ (axis·sin(q/2), cos(q/2)), which is linear in
        # sin and cos: origin ⊗ (axis, 0) · sin + origin · cos. A prismatic joint moves its
        # child along the axis turned into the parent frame. Both parts are fixed per joint.
        self.half = np.where(prismatic, 0.0, 0.5)
        self.turn = _multiply(self.origin_quat,
                              np.concatenate([self.axis, np.zeros((len(moving), 1))], axis=1))
        self.slide = _rotate(self.origin_quat, self.axis) * prismatic[:, None]

    def transforms(self, positions: np.ndarray,
                   rows: np.ndarray | slice = slice(None)) -> tuple[np.ndarray, np.ndarray]:
        """(translations n×3, quaternions n×4 x y z w) of the moving joints `rows` (all by
        default) at `positions` (one per row)."""
        q = np.asarray(positions, dtype=float)
        half = q * self.half[rows]
        quat = self.turn[rows] * np.sin(half)[:, None] + \
            self.origin_quat[rows] * np.cos(half)[:, None]
        translation = self.origin_xyz[rows] + self.slide[rows] * q[:, None]
        return translation, quat


def _joint(element: ET.Element, label: str) -> Joint:
    name = element.get("name", "")
    kind = element.get("type", "")
    if kind not in (*MOVING, "fixed", "floating", "planar"):
        raise LaunchError(f"{label}: joint '{name}' has type '{kind}'; expected revolute, "
                          "continuous, prismatic, fixed, floating or planar")
    parent, child = element.find("parent"), element.find("child")  # checked by root_link
    assert parent is not None and child is not None
    origin = element.find("origin")
    xyz = _vector(origin.get("xyz") if origin is not None else None, (0.0, 0.0, 0.0), name)
    rpy = _vector(origin.get("rpy") if origin is not None else None, (0.0, 0.0, 0.0), name)
    axis_element = element.find("axis")
    axis = _vector(axis_element.get("xyz") if axis_element is not None else None,
                   (1.0, 0.0, 0.0), name)
    mimic_element = element.find("mimic")
    mimic = None
    if mimic_element is not None:
        mimic = (mimic_element.get("joint", ""), float(mimic_element.get("multiplier", "1")),
                 float(mimic_element.get("offset", "0")))
    return Joint(name, kind, parent.get("link", ""), child.get("link", ""), xyz,
                 rpy_quaternion(*rpy), axis, mimic)


def _vector(text: str | None, default: tuple[float, float, float],
            joint: str) -> tuple[float, float, float]:
    if text is None:
        return default
    try:
        values = tuple(float(v) for v in text.split())
    except ValueError:
        values = ()
    if len(values) != 3:
        raise LaunchError(f"joint '{joint}': expected three numbers, got '{text}'")
    return values  # type: ignore[return-value]


def rpy_quaternion(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    """URDF's fixed-axis roll, pitch, yaw as a quaternion (x, y, z, w)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def _multiply(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise quaternion products a ⊗ b (x y z w)."""
    ax, ay, az, aw = a.T
    bx, by, bz, bw = b.T
    return np.stack([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz], axis=1)


def _rotate(quat: np.ndarray, vectors: np.ndarray) -> np.ndarray:
    """Row-wise rotation of vectors by quaternions (x y z w)."""
    u, w = quat[:, :3], quat[:, 3:4]
    t = 2 * np.cross(u, vectors)
    return vectors + w * t + np.cross(u, t)
