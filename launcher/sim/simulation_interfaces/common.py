"""What the parts of the standard API share: the node and server they serve, Result codes,
and reading and writing geometry_msgs poses."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from launcher.sim.transform import IDENTITY, Pose

TYPES = "simulation_interfaces"

# Result.result
FEATURE_UNSUPPORTED, OK, NOT_FOUND, INCORRECT_STATE, OPERATION_FAILED = range(5)
WORLD_FRAMES = ("", "world", "/world", "map", "/map")
NO_WORLD_TEXT = "no world is loaded (UnloadWorld removed it): LoadWorld one first"


@dataclass
class Api:
    node: Any  # the `gzserver` node
    server: Any  # the sim's loop (sim/runner.py): its world, pausing and stepping

    @property
    def world(self) -> Any:
        return self.server.world

    def frame(self, name: str) -> Pose | None:
        """The pose of a reference frame: the world, or an entity's model frame; None for a
        frame the sim does not know."""
        if name.strip() in WORLD_FRAMES:
            return IDENTITY
        entities = self.world.entities
        if name not in entities:
            return None
        return entity_pose(self.world, name)


def result(response: Any, code: int, message: str = "") -> Any:
    response.result.result, response.result.error_message = code, message
    return response


def entity_pose(world: Any, name: str) -> Pose:
    """An entity's model frame in the world."""
    entity = world.entities[name]
    pose = world.placement.body_pose(entity.body)
    return pose * entity.offset.inverse() if not entity.offset.is_identity else pose


def pose_of(message: Any) -> Pose:
    """A geometry_msgs/Pose; an all-zero quaternion (a message left at its zeros) is the
    identity. ValueError for a non-finite value or a quaternion that is no rotation."""
    p, q = message.position, message.orientation
    position = (p.x, p.y, p.z)
    quat = (q.w, q.x, q.y, q.z)
    if not all(math.isfinite(v) for v in (*position, *quat)):
        raise ValueError("the pose holds a value that is not a finite number")
    if all(v == 0 for v in quat):
        return Pose(position, (1.0, 0.0, 0.0, 0.0))
    norm = math.sqrt(sum(v * v for v in quat))
    if abs(norm - 1.0) > 0.01:
        raise ValueError(f"the orientation (x={q.x:g}, y={q.y:g}, z={q.z:g}, w={q.w:g}) is not "
                         f"a unit quaternion (its norm is {norm:g})")
    return Pose(position, tuple(v / norm for v in quat))


def fill_pose(message: Any, pose: Pose) -> None:
    message.position.x, message.position.y, message.position.z = pose.pos
    o = message.orientation
    o.w, o.x, o.y, o.z = pose.quat


def fill_vector(message: Any, values: Any) -> None:
    message.x, message.y, message.z = (float(v) for v in values)


