"""A link's `<inertial>`: mass, centre of mass and inertia tensor, checked.

The tensor is turned from the inertial frame into the link frame and given to MuJoCo whole
(`fullinertia`). A link without `<inertial>` has SDF's default (1 kg, unit inertia);
`<inertial auto="true">` leaves it to MuJoCo to compute from the collisions at `<density>`.
Static links may have any mass (they never move); a moving link's mass and tensor must be
physical.
"""

from __future__ import annotations

import math
from typing import Any

from launcher.sim.sdf.pose import Quat, number, parse_pose
from launcher.sim.sdf.xmltree import Element

TENSOR = ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")
DEFAULT_DENSITY = 1000.0


def set_inertial(body: Any, link: Element, static: bool) -> None:
    inertial = link.find("inertial")
    if inertial is not None and inertial.get("auto", "false").lower() in ("true", "1"):
        density = inertial.find("density")
        value = number(density, "a density") if density is not None else DEFAULT_DENSITY
        for geom in body.geoms:
            if geom.contype:  # collisions; visuals have density 0
                geom.density = value
        return
    mass, tensor, pose = 1.0, [1.0, 1.0, 1.0, 0.0, 0.0, 0.0], parse_pose(None)
    if inertial is not None:
        mass = _mass(inertial, static)
        tensor = _tensor(inertial, static, link.get("name", ""))
        pose = parse_pose(inertial.find("pose"))
    body.explicitinertial = True
    body.mass = max(mass, 1e-9) if static else mass
    body.ipos = list(pose.pos)
    body.fullinertia = _off_the_bound(_rotated(tensor, pose.quat)) if not static else \
        [max(v, 1e-9) if i < 3 else 0.0 for i, v in enumerate(tensor)]


def _mass(inertial: Element, static: bool) -> float:
    element = inertial.find("mass")
    mass = number(element, "a mass in kg") if element is not None else 1.0
    if mass <= 0 and not static:
        raise (element or inertial).error(f"<mass> must be > 0 for a link that moves, got "
                                          f"{mass:g} (make the model <static> if it never "
                                          "moves)")
    return mass


def _tensor(inertial: Element, static: bool, link: str) -> list[float]:
    element = inertial.find("inertia")
    defaults = {"ixx": 1.0, "iyy": 1.0, "izz": 1.0, "ixy": 0.0, "ixz": 0.0, "iyz": 0.0}
    if element is not None:
        for tag in TENSOR:
            child = element.find(tag)
            if child is not None and child.text and not child.text.isspace():
                defaults[tag] = number(child)
    tensor = [defaults[t] for t in TENSOR]
    if not static and not _positive_definite(tensor):
        raise (element or inertial).error(
            f"link '{link}': the inertia tensor (ixx iyy izz ixy ixz iyz = "
            f"{' '.join(f'{v:g}' for v in tensor)}) is not positive definite: every principal "
            "moment must be > 0 and each no larger than the sum of the other two")
    return tensor


def _positive_definite(tensor: list[float]) -> bool:
    xx, yy, zz, xy, xz, yz = tensor
    minors = (xx, xx * yy - xy * xy,
              xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz))
    if min(minors) <= 0:
        return False
    moments = _eigenvalues(tensor)
    return all(m > 0 for m in moments) and \
        max(moments) <= (sum(moments) - max(moments)) * (1 + 1e-6)


def _off_the_bound(tensor: list[float]) -> list[float]:
    """A thin plate's moments sit on the bound (A + B = C), where rounding in the rotation can
    put them past it for MuJoCo: widen the diagonal by that much (a few parts per billion)."""
    moments = _eigenvalues(tensor)
    gap = max(moments) - (sum(moments) - max(moments)) + 1e-9 * sum(moments)
    if gap <= 0 and tensor[3:] == [0.0, 0.0, 0.0]:
        return tensor  # diagonal and off the bound: no rounding to fear
    if gap <= 0:
        return tensor
    return [v + gap if i < 3 else v for i, v in enumerate(tensor)]


def _eigenvalues(tensor: list[float]) -> list[float]:
    """Of a symmetric 3×3 matrix (closed form)."""
    xx, yy, zz, xy, xz, yz = tensor
    p1 = xy * xy + xz * xz + yz * yz
    if p1 == 0:
        return [xx, yy, zz]
    q = (xx + yy + zz) / 3
    p = math.sqrt(((xx - q) ** 2 + (yy - q) ** 2 + (zz - q) ** 2 + 2 * p1) / 6)
    b = [[(xx - q) / p, xy / p, xz / p], [xy / p, (yy - q) / p, yz / p],
         [xz / p, yz / p, (zz - q) / p]]
    det = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1])
           - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
           + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]))
    phi = math.acos(max(-1.0, min(1.0, det / 2))) / 3
    first = q + 2 * p * math.cos(phi)
    third = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return [first, 3 * q - first - third, third]


def _rotated(tensor: list[float], quat: Quat) -> list[float]:
    """R I Rᵀ, as MuJoCo's fullinertia (xx yy zz xy xz yz)."""
    if quat == (1.0, 0.0, 0.0, 0.0):
        return tensor
    xx, yy, zz, xy, xz, yz = tensor
    inertia = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]
    w, x, y, z = quat
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    ri = [[sum(r[i][k] * inertia[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    out = [[sum(ri[i][k] * r[j][k] for k in range(3)) for j in range(3)] for i in range(3)]
    return [out[0][0], out[1][1], out[2][2], out[0][1], out[0][2], out[1][2]]
