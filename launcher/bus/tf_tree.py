"""The tf tree (tf2's core, for tf2_ros and the tf tools): frames whose transforms change
over time, looked up between any two frames at a time, interpolated (linear for translation,
slerp for rotation) as tf2 does.

Each frame keeps its transforms to its parent, newest last, for `cache_time`; a static frame
keeps one for ever. A lookup walks both frames up to their common ancestor at the time asked
(time 0: the latest time every frame on the way has data for) and composes the transforms.
The errors are tf2's, with what helps: the frames that exist, and the window of times there
is data for. Poses are plain tuples: lookups are many and small (the cost is CPython's).
"""

from __future__ import annotations

import bisect
import math
import threading
from typing import Any, NamedTuple

Vector = tuple[float, float, float]
Quat = tuple[float, float, float, float]  # x, y, z, w (ROS's order)
IDENTITY: tuple[Vector, Quat] = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
MAX_DEPTH = 1000  # tf2's limit on a chain, against a loop


class TransformException(Exception):
    pass


class LookupException(TransformException):
    pass


class ConnectivityException(TransformException):
    pass


class ExtrapolationException(TransformException):
    pass


class InvalidArgumentException(TransformException):
    pass


class TimeoutException(TransformException):
    pass


def multiply(a: tuple[Vector, Quat], b: tuple[Vector, Quat]) -> tuple[Vector, Quat]:
    """a then b expressed in a (parent_T_child composition)."""
    (ax, ay, az), (qx, qy, qz, qw) = a
    (bx, by, bz), (rx, ry, rz, rw) = b
    # rotate b's translation by a's rotation: v + 2w(q×v) + 2q×(q×v)
    cx, cy, cz = qy * bz - qz * by, qz * bx - qx * bz, qx * by - qy * bx
    tx = bx + 2 * (qw * cx + qy * cz - qz * cy)
    ty = by + 2 * (qw * cy + qz * cx - qx * cz)
    tz = bz + 2 * (qw * cz + qx * cy - qy * cx)
    return ((ax + tx, ay + ty, az + tz),
            (qw * rx + qx * rw + qy * rz - qz * ry, qw * ry - qx * rz + qy * rw + qz * rx,
             qw * rz + qx * ry - qy * rx + qz * rw, qw * rw - qx * rx - qy * ry - qz * rz))


def inverse(a: tuple[Vector, Quat]) -> tuple[Vector, Quat]:
    (x, y, z), (qx, qy, qz, qw) = a
    return multiply(((0.0, 0.0, 0.0), (-qx, -qy, -qz, qw)), ((-x, -y, -z), (0.0, 0.0, 0.0, 1.0)))


def _interpolate(a: tuple[Vector, Quat], b: tuple[Vector, Quat], ratio: float
                 ) -> tuple[Vector, Quat]:
    (ax, ay, az), qa = a
    (bx, by, bz), qb = b
    dot = sum(x * y for x, y in zip(qa, qb, strict=True))
    if dot < 0:  # the short way round
        qb, dot = tuple(-v for v in qb), -dot  # type: ignore[assignment]
    if dot > 0.9995:
        q = tuple(x + (y - x) * ratio for x, y in zip(qa, qb, strict=True))
    else:
        theta = math.acos(min(dot, 1.0))
        s = math.sin(theta)
        wa, wb = math.sin((1 - ratio) * theta) / s, math.sin(ratio * theta) / s
        q = tuple(wa * x + wb * y for x, y in zip(qa, qb, strict=True))
    norm = math.sqrt(sum(v * v for v in q))
    return ((ax + (bx - ax) * ratio, ay + (by - ay) * ratio, az + (bz - az) * ratio),
            tuple(v / norm for v in q))  # type: ignore[return-value]


class Edge(NamedTuple):
    """A frame and its newest parent; the times (ns) of its oldest and newest transforms and
    how many it keeps (a static frame keeps none)."""
    name: str
    parent: str
    authority: str
    static: bool
    oldest: int
    newest: int
    count: int


class _Frame:
    """One frame's transforms to its parent: (time ns, parent, pose), oldest first."""

    __slots__ = ("times", "entries", "static", "authority")

    def __init__(self) -> None:
        self.times: list[int] = []
        self.entries: list[tuple[str, tuple[Vector, Quat]]] = []
        self.static = False
        self.authority = ""

    def at(self, stamp: int) -> tuple[str, tuple[Vector, Quat]] | None:
        """(parent, pose) at `stamp`, interpolated; None if out of the data's window."""
        if self.static:
            return self.entries[-1]
        times = self.times
        if not times:
            return None
        if stamp == times[-1]:
            return self.entries[-1]
        if stamp > times[-1] or stamp < times[0]:
            return None
        i = bisect.bisect_left(times, stamp)
        if times[i] == stamp:
            return self.entries[i]
        (pa, a), (pb, b) = self.entries[i - 1], self.entries[i]
        if pa != pb:  # re-parented in between: no interpolation across it
            return self.entries[i]
        return pa, _interpolate(a, b, (stamp - times[i - 1]) / (times[i] - times[i - 1]))


class BufferCore:
    def __init__(self, cache_time_ns: int = 10 * 1_000_000_000) -> None:
        self.cache_time = cache_time_ns
        self._frames: dict[str, _Frame] = {}
        self._lock = threading.RLock()
        self._version = 0  # changes with every transform set
        self._cache: dict[tuple[str, str, int], tuple[int, Any]] = {}
        self._reparented: set[tuple[str, str]] = set()
        self.warn: Any = None  # a logger's warning method, for a frame given two parents

    # --- setting ---------------------------------------------------------------------------
    def set_transform(self, child: str, parent: str, stamp: int, pose: tuple[Vector, Quat],
                      authority: str = "", static: bool = False) -> None:
        child, parent = child.lstrip("/"), parent.lstrip("/")
        if not child or not parent:
            raise InvalidArgumentException(
                f"TF_NO_{'CHILD' if not child else 'FRAME'}_ID: ignoring transform from "
                f"authority \"{authority}\" because {'child_frame_id' if not child else 'frame_id'}"
                " is not set")
        if child == parent:
            raise InvalidArgumentException(
                f"TF_SELF_TRANSFORM: ignoring transform from authority \"{authority}\" with "
                f"frame_id and child_frame_id \"{child}\" because they are the same")
        if not all(math.isfinite(v) for v in (*pose[0], *pose[1])):
            raise InvalidArgumentException(
                f"TF_NAN_INPUT: ignoring transform for child_frame_id \"{child}\" from "
                f"authority \"{authority}\" because of a nan value in the transform")
        with self._lock:
            frame = self._frames.get(child)
            if frame is None:
                frame = self._frames[child] = _Frame()
            if frame.entries and frame.entries[-1][0] != parent and \
                    (child, parent) not in self._reparented:
                self._reparented.add((child, parent))
                if self.warn is not None:
                    self.warn(f"frame '{child}' has two parents: '{frame.entries[-1][0]}' "
                              f"(from \"{frame.authority}\") and now '{parent}' (from "
                              f"\"{authority}\"); a frame has one parent, so the newest "
                              "transform's parent wins, as in tf2")
            frame.authority = authority
            if static:
                frame.static = True
                frame.times, frame.entries = [stamp], [(parent, pose)]
            elif not frame.times or stamp > frame.times[-1]:
                frame.times.append(stamp)
                frame.entries.append((parent, pose))
            else:
                i = bisect.bisect_left(frame.times, stamp)
                if i < len(frame.times) and frame.times[i] == stamp:
                    frame.entries[i] = (parent, pose)  # TF_REPEATED_DATA: the newer wins
                else:
                    frame.times.insert(i, stamp)
                    frame.entries.insert(i, (parent, pose))
            if not frame.static:
                cut = bisect.bisect_left(frame.times, frame.times[-1] - self.cache_time)
                if cut:
                    del frame.times[:cut], frame.entries[:cut]
            self._version += 1

    def clear(self) -> None:
        with self._lock:
            self._frames.clear()
            self._version += 1

    # --- reading ---------------------------------------------------------------------------
    def frames(self) -> list[str]:
        with self._lock:
            names = set(self._frames)
            for frame in self._frames.values():
                names.update(parent for parent, _ in frame.entries)
        return sorted(names)

    def edges(self) -> list[Edge]:
        """Each frame that has a parent, by name, with what tf2_tools tells of it."""
        with self._lock:
            return [Edge(name, frame.entries[-1][0], frame.authority, frame.static,
                         frame.times[0] if frame.times else 0,
                         frame.times[-1] if frame.times else 0, len(frame.times))
                    for name, frame in sorted(self._frames.items()) if frame.entries]

    def _exists(self, name: str) -> bool:
        return name in self._frames or any(p == name for f in self._frames.values()
                                           for p, _ in f.entries[-1:])

    def lookup(self, target: str, source: str, stamp: int) -> tuple[tuple[Vector, Quat], int]:
        """(target_T_source, the time it is at): `stamp` 0 for the latest common time."""
        target, source = target.lstrip("/"), source.lstrip("/")
        key = (target, source, stamp)
        with self._lock:
            cached = self._cache.get(key)
            if cached is not None and cached[0] == self._version:
                return cached[1]
            found = self._lookup(target, source, stamp)
            if len(self._cache) > 4096:
                self._cache.clear()
            self._cache[key] = (self._version, found)
            return found

    def _lookup(self, target: str, source: str, stamp: int
                ) -> tuple[tuple[Vector, Quat], int]:
        for name, argument in ((target, "target_frame"), (source, "source_frame")):
            if not name:
                raise InvalidArgumentException(f"Invalid argument passed to lookupTransform "
                                               f"argument {argument} in tf2 frame_ids cannot "
                                               "be empty")
            if not self._exists(name):
                raise LookupException(
                    f"\"{name}\" passed to lookupTransform argument {argument} does not exist. "
                    f"{self._known()}")
        if target == source:
            return IDENTITY, stamp or self._latest(source)
        if stamp == 0:
            stamp = self.common_time(target, source)
        up_source = self._chain(source, stamp, target, source)
        if up_source[-1][0] == target:
            return _compose(up_source), stamp
        up_target = self._chain(target, stamp, target, source)
        source_names = {name: i for i, (name, _) in enumerate(up_source)}
        for j, (name, _) in enumerate(up_target):
            if name in source_names:
                i = source_names[name]
                return multiply(inverse(_compose(up_target[:j + 1])),
                                _compose(up_source[:i + 1])), stamp
        raise ConnectivityException(
            f"Could not find a connection between '{target}' and '{source}' because they are "
            "not part of the same tree.Tf has two or more unconnected trees.")

    def _chain(self, start: str, stamp: int, target: str, source: str
               ) -> list[tuple[str, tuple[Vector, Quat]]]:
        """[(frame, ancestor_T_that frame so far)…] from `start` up to its root, at `stamp`:
        entry k holds (name of the k-th frame up, the pose of the previous one in it)."""
        chain: list[tuple[str, tuple[Vector, Quat]]] = [(start, IDENTITY)]
        name = start
        for _ in range(MAX_DEPTH):
            frame = self._frames.get(name)
            if frame is None:  # a root
                return chain
            found = frame.at(stamp)
            if found is None:
                raise ExtrapolationException(self._extrapolation(frame, stamp, target, source))
            parent, pose = found
            chain.append((parent, pose))
            name = parent
        raise LookupException(f"the tf tree has a loop through '{start}' (more than "
                              f"{MAX_DEPTH} frames up)")

    def _latest(self, name: str) -> int:
        frame = self._frames.get(name)
        return frame.times[-1] if frame is not None and frame.times and not frame.static else 0

    def common_time(self, target: str, source: str) -> int:
        """tf2's latest common time: the oldest of the newest data on both chains (0: all
        static)."""
        newest: list[int] = []
        for start in (target, source):
            name = start
            for _ in range(MAX_DEPTH):
                frame = self._frames.get(name)
                if frame is None or not frame.entries:
                    break
                if not frame.static:
                    newest.append(frame.times[-1])
                name = frame.entries[-1][0]
        return min(newest) if newest else 0

    def _extrapolation(self, frame: _Frame, stamp: int, target: str, source: str) -> str:
        first, last = frame.times[0] / 1e9, frame.times[-1] / 1e9
        asked = stamp / 1e9
        where = "into the future" if asked > last else "into the past"
        edge = f"the latest data is at time {last:.6f}" if asked > last else \
            f"the earliest data is at time {first:.6f}"
        return (f"Lookup would require extrapolation {where}.  Requested time {asked:.6f} but "
                f"{edge}, when looking up transform from frame [{source}] to frame [{target}]"
                f" (data from {first:.6f} to {last:.6f})")

    def _known(self) -> str:
        names = self.frames()
        return f"Known frames: {', '.join(names)}" if names else "No frames are known yet."

    def can_transform(self, target: str, source: str, stamp: int) -> tuple[bool, str]:
        try:
            self.lookup(target, source, stamp)
        except TransformException as exc:
            return False, str(exc)
        return True, ""

    def as_yaml(self) -> str:
        lines = []
        with self._lock:
            for name in sorted(self._frames):
                frame = self._frames[name]
                if not frame.entries:
                    continue
                newest = 0.0 if frame.static else frame.times[-1] / 1e9
                oldest = 0.0 if frame.static else frame.times[0] / 1e9
                span = newest - oldest
                rate = (len(frame.times) - 1) / span if span > 0 else 10000.0
                lines += [f"{name}: ", f"  parent: '{frame.entries[-1][0]}'",
                          f"  broadcaster: '{frame.authority}'", f"  rate: {rate:.3f}",
                          f"  most_recent_transform: {newest:.6f}",
                          f"  oldest_transform: {oldest:.6f}", f"  buffer_length: {span:.3f}"]
        return "\n".join(lines) + ("\n" if lines else "")


def _compose(chain: list[tuple[str, tuple[Vector, Quat]]]) -> tuple[Vector, Quat]:
    """ancestor_T_start for a chain from _chain (each entry: the previous frame in this one)."""
    pose = IDENTITY
    for _, step in reversed(chain[1:]):
        pose = multiply(pose, step) if pose is not IDENTITY else step
    return pose
