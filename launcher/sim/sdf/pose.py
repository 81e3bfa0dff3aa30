"""SDF's `<pose>` (`x y z roll pitch yaw`, or `quat_xyzw`, in degrees or radians) and lists of
numbers in SDF elements, checked with the element's place in errors."""

from __future__ import annotations

import math

from launcher.sim.sdf.xmltree import Element
from launcher.sim.transform import IDENTITY, Pose, Quat, Vector, from_rpy, rotate

__all__ = ["IDENTITY", "Pose", "Quat", "Vector", "from_rpy", "rotate", "number", "numbers",
           "parse_pose"]
_INFINITIES = (math.inf, -math.inf)


def number(element: Element, what: str = "a number") -> float:
    """One finite number (the fast path of `numbers`: most SDF values are one number)."""
    try:
        value = float(element.text)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return numbers(element, 1, what)[0]  # raises with the element's place
    if value != value or value in _INFINITIES:
        return numbers(element, 1, what)[0]
    return value


def child_number(element: Element, tag: str, default: float = 0.0) -> float:
    """The one finite number of `element`'s child `tag`; `default` where it has none."""
    child = element.find(tag)
    if child is None or not child.stripped:
        return default
    return number(child)


def numbers(element: Element, count: int | tuple[int, ...], what: str) -> list[float]:
    """The whitespace-separated numbers of an element, exactly `count` of them."""
    counts = (count,) if isinstance(count, int) else count
    try:
        values = list(map(float, element.text.split())) if element.text else []
    except ValueError:
        raise element.error(f"<{element.tag}>: expected {what}, got '{element.stripped}'") from None
    if len(values) not in counts or not all(map(math.isfinite, values)):
        raise element.error(f"<{element.tag}>: expected {what}, got '{element.stripped}'")
    return values


def parse_pose(element: Element | None) -> Pose:
    """A `<pose>` element (euler_rpy, quat_xyzw, degrees) as a Pose; none is the identity."""
    if element is None or not element.stripped:
        return IDENTITY
    if element.get("rotation_format", "euler_rpy") == "quat_xyzw":
        x, y, z, qx, qy, qz, qw = numbers(element, 7, "x y z qx qy qz qw")
        norm = math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz)
        if norm < 1e-12:
            raise element.error("<pose>: the quaternion is zero")
        return Pose((x, y, z), (qw / norm, qx / norm, qy / norm, qz / norm))
    values = numbers(element, 6, "six numbers: x y z roll pitch yaw")
    if element.get("degrees", "false").lower() in ("true", "1"):
        values[3:] = [math.radians(v) for v in values[3:]]
    return from_rpy(*values)
