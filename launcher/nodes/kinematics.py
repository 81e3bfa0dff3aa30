"""A URDF's joint tree and its forward kinematics.

`Tree.parse(text)` checks the URDF (XML, one root, no loops, joints naming real links) and
keeps each joint's origin, axis, type and mimic. An SDF `<model>` is read as sdformat_urdf
reads it for ROS 2's robot_state_publisher (what ros_gz's demos feed it): its links (nested
ones by their scoped names) and joints, each joint's origin the child link's pose in the
parent link's frame and its axis in the child's; a joint to `world` is left out.
`Tree.transforms(positions)` gives, for the moving joints, the parent → child transform
(translation, quaternion x y z w), as robot_state_publisher publishes them on /tf. Fixed
joints' transforms are constant (`Tree.fixed`). Floating and planar joints are skipped, as
ROS's robot_state_publisher does.

Plain Python, no numpy: what is fixed per joint is worked out once, so a joint costs one sine,
one cosine and a few products per message (20 joints at 1 kHz: a few % of a core), and the
node starts without numpy's ~0.1 s import.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass, field

from launcher.errors import LaunchError
from launcher.sim.transform import IDENTITY as _IDENTITY
from launcher.sim.urdf_tree import parse_robot, root_link

MOVING = ("revolute", "continuous", "prismatic")
_PROLOGUE = re.compile(r"^\s*(?:<\?.*?\?>|<!--.*?-->|\s)*", re.S)  # <?xml?>, comments
# SDF's joints as sdformat_urdf converts them (ball and universal: floating, since 1.0.0)
_SDF_KINDS = {"revolute": "revolute", "continuous": "continuous", "prismatic": "prismatic",
              "fixed": "fixed", "ball": "floating", "universal": "floating"}


def _unlimited(limit: ET.Element, unlimited: float) -> bool:
    """SDF writes no limit as ±1e16 (or leaves <lower>/<upper> out)."""
    try:
        lower = float(limit.findtext("lower", "-1e16"))
        upper = float(limit.findtext("upper", "1e16"))
    except ValueError:
        return False
    return lower <= -unlimited and upper >= unlimited


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
        if _PROLOGUE.sub("", text).lstrip().startswith("<sdf"):
            return cls._from_sdf(text, label)
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

    @classmethod
    def _from_sdf(cls, text: str, label: str) -> Tree:
        # the SDF reader (and the MuJoCo it brings) only when a description is SDF
        from launcher.sim.sdf.context import Context, top_element
        from launcher.sim.sdf.parts import UNLIMITED, Parts, canonical_link, collect, tree

        element, origin = top_element(text, None, "model", ": robot_state_publisher takes a "
                                                           "<model>")
        parts = Parts()
        context = Context({}, None)
        with context.inside(origin):
            collect(element, origin, context, "", _IDENTITY, parts)
        parents = tree(parts, element)
        joints = []
        for child, joint in parents.items():
            if joint.parent == "world":
                continue
            kind = _SDF_KINDS.get(joint.kind)
            if kind is None:
                raise LaunchError(f"{label}: joint '{joint.name}' is a {joint.kind} joint, which "
                                  f"robot_state_publisher cannot follow (as sdformat_urdf: "
                                  f"revolute, continuous, prismatic and fixed joints; ball "
                                  f"and universal ones as floating)")
            limit = joint.element.find("axis")
            limit = limit.find("limit") if limit is not None else None
            if kind == "revolute" and (limit is None or _unlimited(limit, UNLIMITED)):
                kind = "continuous"
            parent_pose, child_pose = parts.links[joint.parent].pose, parts.links[child].pose
            relative = parent_pose.inverse() * child_pose
            w, x, y, z = relative.quat
            cw, cx, cy, cz = child_pose.quat
            axis = _rotate((-cx, -cy, -cz, cw), joint.axes[0]) if joint.axes else (1.0, 0, 0)
            joints.append(Joint(joint.name, kind, joint.parent, child, relative.pos,
                                (x, y, z, w), axis))
        root = canonical_link(element, parts)
        while root in parents and parents[root].parent != "world":
            root = parents[root].parent
        tree_ = cls(element.get("name", ""), root, joints)
        tree_.moving = [j for j in joints if j.kind in MOVING]
        tree_.fixed = [j for j in joints if j.kind == "fixed"]
        tree_._arrays()
        return tree_

    def _arrays(self) -> None:
        """Per moving joint: its origin, how it slides (prismatic), the quaternions of its turn
        (revolute): origin ⊗ (axis·sin(q/2), cos(q/2)) is linear in sin and cos, so
        turn·sin + origin·cos with turn = origin ⊗ (axis, 0)."""
        self.index = {j.name: i for i, j in enumerate(self.moving)}
        self._parts: list[tuple[float, ...]] = []
        for joint in self.moving:
            ax, ay, az = joint.axis
            norm = math.sqrt(ax * ax + ay * ay + az * az)
            axis = (ax / norm, ay / norm, az / norm) if norm > 0 else (0.0, 0.0, 0.0)
            prismatic = joint.kind == "prismatic"
            slide = _rotate(joint.quat, axis) if prismatic else (0.0, 0.0, 0.0)
            turn = _multiply(joint.quat, (*axis, 0.0))
            self._parts.append((*joint.xyz, *slide, 0.0 if prismatic else 0.5, *turn,
                                *joint.quat))

    def transforms(self, positions: Sequence[float], rows: Sequence[int] | None = None
                   ) -> tuple[list[tuple[float, float, float]],
                              list[tuple[float, float, float, float]]]:
        """(translations, quaternions x y z w) of the moving joints `rows` (all by default)
        at `positions` (one per row)."""
        parts = self._parts if rows is None else [self._parts[row] for row in rows]
        translations, quats = [], []
        sin, cos = math.sin, math.cos
        for q, (ox, oy, oz, sx, sy, sz, half, tx, ty, tz, tw, qx, qy, qz, qw) in zip(
                positions, parts, strict=True):
            q = float(q)
            s, c = sin(q * half), cos(q * half)
            translations.append((ox + sx * q, oy + sy * q, oz + sz * q))
            quats.append((tx * s + qx * c, ty * s + qy * c, tz * s + qz * c, tw * s + qw * c))
        return translations, quats


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


def _multiply(a: Sequence[float], b: Sequence[float]) -> tuple[float, float, float, float]:
    """The quaternion product a ⊗ b (x y z w)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def _rotate(quat: Sequence[float], vector: Sequence[float]) -> tuple[float, float, float]:
    """`vector` rotated by `quat` (x y z w)."""
    ux, uy, uz, w = quat
    vx, vy, vz = vector
    tx, ty, tz = 2 * (uy * vz - uz * vy), 2 * (uz * vx - ux * vz), 2 * (ux * vy - uy * vx)
    return (vx + w * tx + (uy * tz - uz * ty), vy + w * ty + (uz * tx - ux * tz),
            vz + w * tz + (ux * ty - uy * tx))
