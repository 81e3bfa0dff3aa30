"""`<collision>` and `<visual>` into MuJoCo geoms: shape, size, colour and friction.

SDF gives full box sizes and cylinder lengths, MuJoCo half ones; a plane's `<normal>` turns
the geom; cones and meshes become mesh assets (a cone as a convex hull of its vertices).
Visuals collide with nothing and sit in geom group 1; collisions in group 3, hidden in
pictures as Gazebo hides them. Shapes MuJoCo has no form for are reported and left out.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import mujoco

from launcher.sim.sdf.pose import Pose, number, numbers
from launcher.sim.sdf.xmltree import Element

VISUAL_GROUP, COLLISION_GROUP = 1, 3
CONE_EDGES = 32
MESH_FORMATS = (".stl", ".obj", ".msh")
UNSUPPORTED = {"heightmap": "a heightmap", "polyline": "a polyline (extruded polygon)",
               "image": "an image extrusion"}
# Gazebo classic's named materials (<material><script><name>Gazebo/Red</name>)
NAMED_COLOURS = {
    "Gazebo/White": (1, 1, 1), "Gazebo/Black": (0, 0, 0), "Gazebo/Grey": (0.7, 0.7, 0.7),
    "Gazebo/DarkGrey": (0.35, 0.35, 0.35), "Gazebo/Red": (1, 0, 0), "Gazebo/Green": (0, 1, 0),
    "Gazebo/Blue": (0, 0, 1), "Gazebo/Yellow": (1, 1, 0), "Gazebo/Orange": (1, 0.5, 0.05),
    "Gazebo/Purple": (0.5, 0, 0.5), "Gazebo/Turquoise": (0, 0.8, 0.8),
    "Gazebo/Wood": (0.6, 0.4, 0.2), "Gazebo/Gold": (0.8, 0.65, 0.2),
}

Warn = Callable[[Element, str], None]
ResolveMesh = Callable[[str, Element], Path]


def add_geom(body: Any, spec: Any, element: Element, pose: Pose, visual: bool, warn: Warn,
             resolve_mesh: ResolveMesh, name: str) -> Any | None:
    """Add `element` (a collision or visual) to `body` at `pose` (in the body frame)."""
    geometry = element.find("geometry")
    shape = next((c for c in geometry.children if c.tag != "empty"), None) \
        if geometry is not None else None
    if shape is None:
        return None  # <geometry><empty/> or none: nothing to add
    what = "visual" if visual else "collision"
    if shape.tag in UNSUPPORTED:
        warn(shape, f"{what} '{element.get('name', '')}' is {UNSUPPORTED[shape.tag]}, which "
                    "MuJoCo cannot express: it is left out (the world lacks that shape)")
        return None
    kwargs = _shape(shape, spec, resolve_mesh, warn, what, element.get("name", ""))
    if kwargs is None:
        return None
    turn = kwargs.pop("turn", None)
    placed = pose * turn if turn is not None else pose
    kwargs.update(name=name, pos=list(placed.pos), quat=list(placed.quat))
    if visual:
        kwargs.update(contype=0, conaffinity=0, group=VISUAL_GROUP, density=0.0,
                      rgba=_colour(element, warn))
    else:
        kwargs.update(group=COLLISION_GROUP, rgba=[0.5, 0.5, 0.5, 1.0])
        mu = element.path("surface", "friction", "ode", "mu")
        sliding = 1.0  # ODE's and MuJoCo's default
        if mu is not None and mu.stripped:
            sliding = max(number(mu, "a friction coefficient"), 0.0)
            kwargs["friction"] = [sliding, 0.005, 0.0001]  # MuJoCo's torsional and rolling
        kwargs["priority"] = friction_priority(sliding)
    geom = body.add_geom()  # attributes one by one: faster than add_geom(**kwargs)
    for key, value in kwargs.items():
        setattr(geom, key, value)
    return geom


def friction_priority(mu: float) -> int:
    """The geom priority that makes a contact take the lower of two frictions, as Gazebo's
    engines combine them (MuJoCo takes the larger unless one geom has priority): the less
    friction, the higher the priority (a caster's mu 0 wins over the ground's 1)."""
    return round(1000 * (MAX_FRICTION - min(max(mu, 0.0), MAX_FRICTION)))


MAX_FRICTION = 100.0


def _shape(shape: Element, spec: Any, resolve_mesh: ResolveMesh, warn: Warn, what: str,
           name: str) -> dict[str, Any] | None:
    g = mujoco.mjtGeom
    tag = shape.tag
    if tag == "box":
        size = shape.find("size")
        x, y, z = numbers(size, 3, "a size 'x y z'") if size is not None else (1.0, 1.0, 1.0)
        if min(x, y, z) <= 0:
            raise shape.error(f"<box><size> must be > 0 in each axis, got {x:g} {y:g} {z:g}")
        return {"type": g.mjGEOM_BOX, "size": [x / 2, y / 2, z / 2]}
    if tag == "sphere":
        return {"type": g.mjGEOM_SPHERE, "size": [_number(shape, "radius", 1.0), 0, 0]}
    if tag in ("cylinder", "capsule"):
        kind = g.mjGEOM_CYLINDER if tag == "cylinder" else g.mjGEOM_CAPSULE
        return {"type": kind, "size": [_number(shape, "radius", 1.0),
                                       _number(shape, "length", 1.0) / 2, 0]}
    if tag == "ellipsoid":
        radii = shape.find("radii")
        return {"type": g.mjGEOM_ELLIPSOID,
                "size": numbers(radii, 3, "radii 'a b c'") if radii is not None else [1, 1, 1]}
    if tag == "plane":
        return _plane(shape)
    if tag == "cone":
        return _cone(shape, spec)
    if tag == "mesh":
        return _mesh(shape, spec, resolve_mesh, warn, what, name)
    warn(shape, f"{what} '{name}': unknown geometry <{tag}>; it is left out")
    return None


def _number(shape: Element, tag: str, default: float) -> float:
    child = shape.find(tag)
    value = number(child) if child is not None else default
    if value <= 0:
        raise child.error(f"<{tag}> must be > 0, got {value:g}") if child is not None else \
            shape.error(f"<{tag}> must be > 0")
    return value


def _plane(shape: Element) -> dict[str, Any]:
    normal = shape.find("normal")
    nx, ny, nz = numbers(normal, 3, "a normal 'x y z'") if normal is not None else (0, 0, 1)
    size = shape.find("size")
    sx, sy = numbers(size, 2, "a size 'x y'") if size is not None else (100.0, 100.0)
    length = math.sqrt(nx * nx + ny * ny + nz * nz) or 1.0
    nx, ny, nz = nx / length, ny / length, nz / length
    # the rotation taking +z to the normal: axis z × n, angle acos(n.z)
    axis, angle = (-ny, nx, 0.0), math.acos(max(-1.0, min(1.0, nz)))
    norm = math.hypot(axis[0], axis[1])
    if norm < 1e-9:
        quat = (1.0, 0.0, 0.0, 0.0) if nz > 0 else (0.0, 1.0, 0.0, 0.0)
    else:
        s = math.sin(angle / 2) / norm
        quat = (math.cos(angle / 2), axis[0] * s, axis[1] * s, 0.0)
    # MuJoCo renders a plane of half sizes; 0 would draw it infinite with a grid spacing
    return {"type": mujoco.mjtGeom.mjGEOM_PLANE, "size": [sx / 2, sy / 2, 1.0],
            "turn": Pose((0.0, 0.0, 0.0), quat)}


def _cone(shape: Element, spec: Any) -> dict[str, Any]:
    radius, length = _number(shape, "radius", 1.0), _number(shape, "length", 1.0)
    name = f"cone_{radius:g}_{length:g}"
    if spec.mesh(name) is None:
        vertices = [0.0, 0.0, length / 2]
        for index in range(CONE_EDGES):
            angle = 2 * math.pi * index / CONE_EDGES
            vertices += [radius * math.cos(angle), radius * math.sin(angle), -length / 2]
        spec.add_mesh(name=name, uservert=vertices)
    return {"type": mujoco.mjtGeom.mjGEOM_MESH, "meshname": name}


def _mesh(shape: Element, spec: Any, resolve_mesh: ResolveMesh, warn: Warn, what: str,
          name: str) -> dict[str, Any] | None:
    uri = shape.value("uri")
    if not uri:
        raise shape.error(f"{what} '{name}': <mesh> needs a <uri>")
    if shape.find("submesh") is not None:
        warn(shape, f"{what} '{name}': <submesh> is not supported; the whole mesh is used")
    path = resolve_mesh(uri, shape)
    if path.suffix.lower() not in MESH_FORMATS:
        warn(shape, f"{what} '{name}': MuJoCo reads STL, OBJ and MSH meshes, not "
                    f"'{path.suffix}' ({path.name}); it is left out (the world lacks that shape)")
        return None
    scale_element = shape.find("scale")
    scale = numbers(scale_element, 3, "a scale 'x y z'") if scale_element is not None \
        else [1.0, 1.0, 1.0]
    mesh_name = f"{path}|{' '.join(f'{s:g}' for s in scale)}"
    if spec.mesh(mesh_name) is None:
        spec.add_mesh(name=mesh_name, file=str(path), scale=scale)
    return {"type": mujoco.mjtGeom.mjGEOM_MESH, "meshname": mesh_name}


def _colour(visual: Element, warn: Warn) -> list[float]:
    material = visual.find("material")
    rgba = [0.7, 0.7, 0.7, 1.0]
    if material is not None:
        for tag in ("diffuse", "ambient"):
            colour = material.find(tag)
            if colour is not None and colour.stripped:
                values = numbers(colour, (3, 4), "a colour 'r g b [a]'")
                rgba = [*values[:3], values[3] if len(values) == 4 else 1.0]
                break
        else:
            script = material.path("script", "name")
            if script is not None and script.stripped in NAMED_COLOURS:
                rgba = [*NAMED_COLOURS[script.stripped], 1.0]
    transparency = visual.find("transparency")
    if transparency is not None and transparency.stripped:
        rgba[3] = max(0.0, min(1.0, 1.0 - number(transparency)))
    return [float(v) for v in rgba]
