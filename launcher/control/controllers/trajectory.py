"""A joint trajectory as joint_trajectory_controller samples it: points at absolute times,
joined by quintic splines where points give positions, velocities and accelerations, cubic
ones where they give positions and velocities, and straight lines where only positions (the
`splines` interpolation; `none` holds each point until the next). The first segment starts at
the state the trajectory was received in; after the last point the last positions hold."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass
class Point:
    time: float
    positions: list[float]
    velocities: list[float] | None = None
    accelerations: list[float] | None = None


def validate(joint_names: list[str], joints: list[str], points: list[Point],
             partial: bool) -> str:
    """Why a trajectory is refused, or ""."""
    if len(set(joint_names)) != len(joint_names):
        return f"joint names {joint_names} hold a name twice"
    unknown = [j for j in joint_names if j not in joints]
    if unknown:
        return f"joints {unknown} are not controlled by this controller (joints: {joints})"
    if not partial and sorted(joint_names) != sorted(joints):
        return (f"the trajectory names joints {joint_names}, expected all of {joints} "
                f"(allow_partial_joints_goal is false)")
    previous = -math.inf
    for index, point in enumerate(points):
        if point.time <= previous:
            return (f"time_from_start of point {index} ({point.time:g} s) is not after the "
                    f"previous point's: times must increase")
        previous = point.time
        for label, values in (("positions", point.positions), ("velocities", point.velocities),
                              ("accelerations", point.accelerations)):
            if values is None:
                continue
            if len(values) != len(joint_names):
                return (f"point {index} has {len(values)} {label} for {len(joint_names)} "
                        f"joints")
            if not all(math.isfinite(v) for v in values):
                return f"point {index} has {label} that are NaN or infinite: {values}"
        if not point.positions and point.velocities is None:
            return f"point {index} has no positions"
    return ""


class Trajectory:
    def __init__(self, start: Point, points: list[Point], interpolate: bool = True) -> None:
        self.points = [start, *points]
        self.interpolate = interpolate
        self.end_time = self.points[-1].time

    def sample(self, t: float) -> tuple[list[float], list[float], list[float]]:
        """Positions, velocities and accelerations at time `t`."""
        points = self.points
        if t >= self.end_time:
            last = points[-1]
            zeros = [0.0] * len(last.positions)
            return list(last.positions), zeros, list(zeros)
        if t <= points[0].time:
            first = points[0]
            zeros = [0.0] * len(first.positions)
            return list(first.positions), list(first.velocities or zeros), list(zeros)
        index = 1
        while points[index].time < t:
            index += 1
        a, b = points[index - 1], points[index]
        if not self.interpolate:
            zeros = [0.0] * len(a.positions)
            return list(a.positions), zeros, list(zeros)
        return _segment(a, b, t)


def _segment(a: Point, b: Point, t: float) -> tuple[list[float], list[float], list[float]]:
    span = b.time - a.time
    s = t - a.time
    count = len(a.positions)
    va, vb = a.velocities, b.velocities
    aa, ab = a.accelerations, b.accelerations
    positions, velocities, accelerations = [], [], []
    for j in range(count):
        p0, p1 = a.positions[j], b.positions[j]
        if vb is None or va is None:  # positions only: a straight line
            rate = (p1 - p0) / span
            positions.append(p0 + rate * s)
            velocities.append(rate)
            accelerations.append(0.0)
            continue
        v0, v1 = va[j], vb[j]
        if ab is None or aa is None:  # cubic Hermite
            c2 = (3 * (p1 - p0) / span - 2 * v0 - v1) / span
            c3 = (2 * (p0 - p1) / span + v0 + v1) / span ** 2
            positions.append(p0 + v0 * s + c2 * s * s + c3 * s ** 3)
            velocities.append(v0 + 2 * c2 * s + 3 * c3 * s * s)
            accelerations.append(2 * c2 + 6 * c3 * s)
            continue
        a0, a1 = aa[j], ab[j]
        T = span  # noqa: N806 - the spline's usual letter
        c3 = (20 * (p1 - p0) - (8 * v1 + 12 * v0) * T - (3 * a0 - a1) * T * T) / (2 * T ** 3)
        c4 = (30 * (p0 - p1) + (14 * v1 + 16 * v0) * T + (3 * a0 - 2 * a1) * T * T) / \
            (2 * T ** 4)
        c5 = (12 * (p1 - p0) - 6 * (v1 + v0) * T - (a0 - a1) * T * T) / (2 * T ** 5)
        positions.append(p0 + v0 * s + a0 / 2 * s * s + c3 * s ** 3 + c4 * s ** 4 + c5 * s ** 5)
        velocities.append(v0 + a0 * s + 3 * c3 * s * s + 4 * c4 * s ** 3 + 5 * c5 * s ** 4)
        accelerations.append(a0 + 6 * c3 * s + 12 * c4 * s * s + 20 * c5 * s ** 3)
    return positions, velocities, accelerations
