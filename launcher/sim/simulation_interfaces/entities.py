"""Entities through the standard API: GetEntities and GetEntitiesStates (with the filters:
a name pattern, categories, tags, bounds), GetEntityState and SetEntityState (pose, twist and
acceleration, in the world or another entity's frame), GetEntityInfo and SetEntityInfo, and
GetEntityBounds (a box around every geom, in the frame of the entity's canonical link).

An entity's category is what SetEntityInfo gave it, else: a static model is a static object,
one with plugins (a drive, ros2_control, sensors) a robot, any other an object. Twists are
in the world frame: a free joint's angular velocity (MuJoCo keeps it in the body's frame) is
turned into it.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from itertools import combinations
from typing import Any

import numpy as np

from launcher.bus.service_table import create_services
from launcher.bus.wire import fill_stamp
from launcher.errors import did_you_mean
from launcher.sim.placement import MAX_SPEED
from launcher.sim.simulation_interfaces.common import (
    NOT_FOUND,
    OK,
    OPERATION_FAILED,
    TYPES,
    Api,
    entity_pose,
    fill_pose,
    fill_vector,
    pose_of,
    result,
)
from launcher.sim.transform import rotate

OBJECT, ROBOT, STATIC_OBJECT = 0, 1, 5
CATEGORIES = (0, 1, 2, 4, 5)
BOX, SPHERE, CONVEX_HULL, EMPTY = 1, 3, 2, 0
ANY, ALL = 0, 1
INVALID_POSE = 101
MAX_HULL_POINTS = 64  # of a convex hull filter (its axes grow as the cube of them)
SIGNS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)


class Refused(Exception):
    """A request answered with a Result code other than OK: (code, message)."""


def answering(handler: Callable[[Any, Any, Any], Any]) -> Callable[[Any, Any, Any], Any]:
    """A service callback whose Refused becomes its answer's Result."""
    @functools.wraps(handler)
    def answer(self: Any, request: Any, response: Any) -> Any:
        try:
            return handler(self, request, response)
        except Refused as refused:
            return result(response, *refused.args)
    return answer


@dataclass
class Info:
    category: int
    description: str = ""
    tags: list[str] = field(default_factory=list)


def info_of(entity: Any) -> Info:
    """Its info as given, else its category: static (Gazebo's `<static>`; a model a joint
    holds to the world is not, as its arm may move), a robot (it has plugins), an object."""
    if entity.info is None:
        category = STATIC_OBJECT if entity.static else ROBOT if entity.plugins else OBJECT
        entity.info = Info(category)
    return entity.info


class Entities:
    def __init__(self, api: Api) -> None:
        self.api = api
        create_services(api.node, TYPES, (
            ("get_entities", "GetEntities", self.on_get_entities),
            ("get_entities_states", "GetEntitiesStates", self.on_get_states),
            ("get_entity_state", "GetEntityState", self.on_get_state),
            ("set_entity_state", "SetEntityState", self.on_set_state),
            ("get_entity_info", "GetEntityInfo", self.on_get_info),
            ("set_entity_info", "SetEntityInfo", self.on_set_info),
            ("get_entity_bounds", "GetEntityBounds", self.on_get_bounds)))

    # --- finding -----------------------------------------------------------------------------
    def entity(self, name: str) -> Any:
        entities = self.api.world.entities
        if name not in entities:
            raise Refused(NOT_FOUND, f"no entity named '{name}'"
                                     f"{did_you_mean(name, list(entities))}; the world has: "
                                     f"{', '.join(entities) or 'none'}")
        return entities[name]

    def matching(self, filters: Any) -> list[str]:
        """The names of the entities that pass every filter given."""
        world = self.api.world
        names = list(world.entities)
        if filters.filter:
            try:
                pattern = re.compile(filters.filter)
            except re.error as exc:
                raise Refused(OPERATION_FAILED, f"filter '{filters.filter}' is not a valid "
                                                f"regular expression: {exc}") from None
            names = [n for n in names if pattern.fullmatch(n)]
        wanted = {c.category for c in filters.categories}
        if wanted:
            names = [n for n in names if info_of(world.entities[n]).category in wanted]
        tags, mode = list(filters.tags.tags), filters.tags.filter_mode
        if mode not in (ANY, ALL):
            raise Refused(OPERATION_FAILED, f"tags filter_mode {mode} is neither "
                                            "FILTER_MODE_ANY (0) nor FILTER_MODE_ALL (1)")
        if tags:
            test = any if mode == ANY else all
            names = [n for n in names
                     if test(t in info_of(world.entities[n]).tags for t in tags)]
        bounds = filters.bounds
        if bounds.type != EMPTY:
            overlaps = _overlap_test(bounds)
            names = [n for n in names if overlaps(*world_box(world, world.entities[n]))]
        return names

    # --- services ----------------------------------------------------------------------------
    @answering
    def on_get_entities(self, request: Any, response: Any) -> Any:
        response.entities = self.matching(request.filters)
        return result(response, OK)

    @answering
    def on_get_states(self, request: Any, response: Any) -> Any:
        names = self.matching(request.filters)
        response.entities = names
        response.states = [self._state(name) for name in names]
        return result(response, OK)

    @answering
    def on_get_state(self, request: Any, response: Any) -> Any:
        self.entity(request.entity)
        response.state = self._state(request.entity)
        return result(response, OK)

    def _state(self, name: str) -> Any:
        world = self.api.world
        entity, data = world.entities[name], world.data
        state = self.api.node.message(f"{TYPES}/msg/EntityState")
        state.header.frame_id = "world"
        fill_stamp(state.header.stamp, float(data.time))
        fill_pose(state.pose, entity_pose(world, name))
        if entity.dof >= 0:
            turn = data.xmat[entity.body].reshape(3, 3)  # the body's frame → the world's
            dof = entity.dof
            fill_vector(state.twist.linear, data.qvel[dof:dof + 3])
            fill_vector(state.twist.angular, turn @ data.qvel[dof + 3:dof + 6])
            fill_vector(state.acceleration.linear, data.qacc[dof:dof + 3])
            fill_vector(state.acceleration.angular, turn @ data.qacc[dof + 3:dof + 6])
        return state

    @answering
    def on_set_state(self, request: Any, response: Any) -> Any:
        """Every part checked before any is applied: a refused request changes nothing."""
        api, state = self.api, request.state
        entity = self.entity(request.entity)
        frame = api.frame(state.header.frame_id)
        if frame is None:
            raise Refused(NOT_FOUND, f"reference frame '{state.header.frame_id}' is neither "
                                 "the world nor an entity")
        twist = [*_vector(state.twist.linear), *_vector(state.twist.angular)]
        acceleration = [*_vector(state.acceleration.linear),
                        *_vector(state.acceleration.angular)]
        static = entity.dof < 0
        for asked, values, what in ((request.set_twist, twist, "a twist"),
                                    (request.set_acceleration, acceleration,
                                     "an acceleration")):
            if asked and static and any(values):
                raise Refused(OPERATION_FAILED, f"'{request.entity}' is static (it has no "
                                            f"free joint): it cannot be given {what}")
        if request.set_twist and not all(math.isfinite(v) and abs(v) <= MAX_SPEED
                                         for v in twist):
            raise Refused(OPERATION_FAILED, f"the twist must be finite numbers within "
                                        f"±{MAX_SPEED:g}")
        pose = None
        if request.set_pose:
            try:
                pose = frame * pose_of(state.pose)
            except ValueError as exc:
                raise Refused(INVALID_POSE, str(exc)) from None
        placement = api.world.placement
        if pose is not None:
            placement.set_pose(request.entity, list(pose.pos), list(pose.quat))
        if request.set_twist and not static:
            placement.set_twist(request.entity, rotate(frame.quat, tuple(twist[:3])),
                                rotate(frame.quat, tuple(twist[3:])))
        api.server.publish_clock()
        ignored = request.set_acceleration and any(acceleration)
        return result(response, OK, "the acceleration is not set: MuJoCo integrates forces, "
                                    "it takes no accelerations" if ignored else "")

    @answering
    def on_get_info(self, request: Any, response: Any) -> Any:
        info = info_of(self.entity(request.entity))
        response.info.category.category = info.category
        response.info.description, response.info.tags = info.description, list(info.tags)
        return result(response, OK)

    @answering
    def on_set_info(self, request: Any, response: Any) -> Any:
        entity = self.entity(request.entity)
        category = request.info.category.category
        if category not in CATEGORIES:
            return result(response, OPERATION_FAILED,
                          f"category {category} is not one of EntityCategory's "
                          f"({', '.join(map(str, CATEGORIES))})")
        entity.info = Info(category, request.info.description, list(request.info.tags))
        return result(response, OK)

    @answering
    def on_get_bounds(self, request: Any, response: Any) -> Any:
        entity = self.entity(request.entity)
        box = local_box(self.api.world, entity)
        if box is None:
            response.bounds.type = EMPTY
        else:
            response.bounds.type = BOX
            response.bounds.points = [self._vector(box[1]), self._vector(box[0])]
        return result(response, OK)

    def _vector(self, values: Any) -> Any:
        vector = self.api.node.message("geometry_msgs/msg/Vector3")
        fill_vector(vector, values)
        return vector


def _vector(message: Any) -> list[float]:
    return [float(message.x), float(message.y), float(message.z)]


# --- bounds ----------------------------------------------------------------------------------
def _corners(world: Any, entity: Any) -> np.ndarray | None:
    """The world-frame corners of every geom's box of the entity (n × 8 × 3), or None."""
    model, data = world.model, world.data
    roots = [model.body(r).id for r in entity.roots] or [entity.body]
    geoms = np.flatnonzero(np.isin(model.body_rootid[model.geom_bodyid], roots))
    if not len(geoms):
        return None
    boxes = model.geom_aabb[geoms]  # centre and half sizes, in each geom's frame
    local = boxes[:, None, :3] + boxes[:, None, 3:] * SIGNS[None]
    turns = data.geom_xmat[geoms].reshape(-1, 3, 3)
    return np.einsum("nij,nkj->nki", turns, local) + data.geom_xpos[geoms][:, None, :]


def world_box(world: Any, entity: Any) -> tuple[np.ndarray, np.ndarray]:
    """The entity's axis-aligned box in the world (low, high corners); an entity without a
    geom is a point at its model frame."""
    corners = _corners(world, entity)
    if corners is None:
        point = np.array(entity_pose(world, entity.name).pos)
        return point, point
    flat = corners.reshape(-1, 3)
    return flat.min(axis=0), flat.max(axis=0)


def local_box(world: Any, entity: Any) -> tuple[np.ndarray, np.ndarray] | None:
    """The box around the entity's geoms in the frame of its canonical link (its root body),
    as GetEntityBounds gives it; None without a geom."""
    corners = _corners(world, entity)
    if corners is None:
        return None
    data = world.data
    turn = data.xmat[entity.body].reshape(3, 3)
    local = (corners.reshape(-1, 3) - data.xpos[entity.body]) @ turn
    return local.min(axis=0), local.max(axis=0)


def _overlap_test(bounds: Any) -> Any:
    """A test of a world box (low, high) against filter bounds: a sphere, a box or a convex
    hull."""
    points = [np.array(_vector(p)) for p in bounds.points]
    if bounds.type == SPHERE:
        if len(points) != 2 or not points[1][0] >= 0:
            raise Refused(OPERATION_FAILED, "sphere bounds need two points: the centre, and "
                                            "one whose x is the radius (≥ 0)")
        centre, radius = points[0], points[1][0]
        return lambda low, high: float(np.linalg.norm(np.clip(centre, low, high) - centre)) \
            <= radius
    if bounds.type == BOX:
        if len(points) != 2:
            raise Refused(OPERATION_FAILED, "box bounds need two points: opposite corners")
        lo, hi = np.minimum(*points), np.maximum(*points)
        return lambda low, high: bool(np.all(low <= hi) and np.all(high >= lo))
    if bounds.type == CONVEX_HULL:
        return _hull_test(np.array(points).reshape(-1, 3))
    raise Refused(OPERATION_FAILED, f"bounds type {bounds.type} is not one of Bounds' types "
                                    "(0 empty, 1 box, 2 convex hull, 3 sphere)")


def serve(api: Api) -> Entities:
    return Entities(api)


def _hull_test(points: np.ndarray) -> Any:
    """A box-against-convex-hull overlap test by separating axes: the two overlap unless
    their shadows on some axis are apart. The axes tried are every plane through three of
    the points (the hull's faces among them), the box's three, and each direction between
    two points crossed with the box's (the edge pairs): enough to find a gap wherever there
    is one (a hull of a few dozen points: a few thousand axes, one matrix product)."""
    if len(points) > MAX_HULL_POINTS:
        raise Refused(OPERATION_FAILED, f"convex hull bounds of {len(points)} points: at "
                                        f"most {MAX_HULL_POINTS} are taken")
    if not np.all(np.isfinite(points)):
        raise Refused(OPERATION_FAILED, "the convex hull's points must be finite numbers")
    i, j, k = (np.array(index) for index in zip(*combinations(range(len(points)), 3),
                                                 strict=True)) \
        if len(points) >= 3 else (np.zeros(0, int),) * 3
    faces = np.cross(points[j] - points[i], points[k] - points[i])
    if not len(faces) or np.max(np.linalg.norm(faces, axis=1)) <= 1e-12:
        raise Refused(OPERATION_FAILED, "convex hull bounds need at least 3 points not on one "
                                        "line")
    a, b = (np.array(index) for index in zip(*combinations(range(len(points)), 2),
                                             strict=True))
    edges = np.cross((points[b] - points[a])[:, None, :], np.eye(3)[None]).reshape(-1, 3)
    axes = np.concatenate([faces, np.eye(3), edges])
    axes = axes[np.linalg.norm(axes, axis=1) > 1e-12]
    shadow = points @ axes.T
    low_hull, high_hull = shadow.min(axis=0), shadow.max(axis=0)

    def overlaps(low: np.ndarray, high: np.ndarray) -> bool:
        corners = (low + high) / 2 + (high - low) / 2 * SIGNS
        box = corners @ axes.T
        return bool(np.all(box.max(axis=0) >= low_hull - 1e-9) and
                    np.all(box.min(axis=0) <= high_hull + 1e-9))
    return overlaps
