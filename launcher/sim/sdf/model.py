"""One SDF `<model>` (nested models and includes flattened into it) as MuJoCo bodies.

Links become bodies named `<prefix><link>` (nested: `<prefix>inner::link`), built as the tree
their joints make; a link without a parent joint is a root: it gets a free joint unless the
model is static, and a joint whose parent is `world` attaches it to the world. Joint frames
and axes are turned into the child body's frame, inertia tensors into the link frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import mujoco

from launcher.errors import did_you_mean
from launcher.sim.sdf import geometry
from launcher.sim.sdf.context import Context, Origin
from launcher.sim.sdf.elements import check_children, plugin_configs
from launcher.sim.sdf.frames import Scope
from launcher.sim.sdf.inertial import set_inertial
from launcher.sim.sdf.pose import IDENTITY, Pose, number, numbers, parse_pose, rotate
from launcher.sim.sdf.xmltree import Element

JOINTS = {"revolute": 1, "continuous": 1, "prismatic": 1, "ball": 1, "fixed": 0,
          "universal": 2, "revolute2": 2, "screw": 1, "gearbox": 0}
UNLIMITED = 1e16  # SDF writes ±1e16 (or ±1.79769e+308) for "no limit"


@dataclass
class Link:
    name: str  # scoped within the model (`inner::link`)
    element: Element
    pose: Pose  # in the model frame
    scope: Scope
    frame: Pose  # the pose of the link's scope (its model) in the model frame
    origin: Origin  # its file: relative mesh URIs start there


@dataclass
class Joint:
    name: str
    element: Element
    kind: str
    parent: str  # a scoped link name, or "world"
    child: str
    pose: Pose  # in the model frame
    axes: list[tuple[float, float, float]]  # unit vectors in the model frame


@dataclass
class Parts:
    links: dict[str, Link] = field(default_factory=dict)
    joints: list[Joint] = field(default_factory=list)
    plugins: list[Any] = field(default_factory=list)
    first_link: str | None = None


@dataclass
class BuiltModel:
    name: str
    root: str  # the body of the canonical link's tree (prefixed)
    offset: Pose  # that body's pose in the model frame
    roots: list[str]  # every root body (prefixed)
    static: bool
    plugins: list[Any]
    pose: Pose  # the model frame in the world


def build(spec: Any, model: Element, origin: Origin, context: Context, prefix: str,
          placement: Pose, static: bool | None = None, name: str | None = None) -> BuiltModel:
    """Add `model` to `spec` under its world body at `placement` (the model frame); `name`
    overrides the model's own (an `<include>`'s `<name>`)."""
    name = name or model.get("name", "")
    if not name:
        raise model.error("<model> needs a name")
    is_static = static if static is not None else _flag(model, "static")
    parts = Parts()
    with context.inside(origin):
        _collect(model, origin, context, "", IDENTITY, parts)
    if not parts.links:
        raise model.error(f"model '{name}' has no <link>")
    parents = _tree(parts, model)
    canonical = _canonical(model, parts)
    roots = [link for link in parts.links if link not in parents or
             parents[link].parent == "world"]
    children: dict[str, list[Joint]] = {}
    for joint in parents.values():
        children.setdefault(joint.parent, []).append(joint)
    builder = _Builder(spec, context, prefix, is_static, parts, children)
    for link in roots:
        builder.body(spec.worldbody, parts.links[link], placement * parts.links[link].pose,
                     parents.get(link))
    root = canonical
    while root in parents and parents[root].parent != "world":
        root = parents[root].parent
    return BuiltModel(name, prefix + root, parts.links[root].pose, [prefix + r for r in roots],
                      is_static, parts.plugins, placement)


def _flag(element: Element, tag: str) -> bool:
    return (element.value(tag, "false") or "").lower() in ("true", "1")


def _collect(model: Element, origin: Origin, context: Context, scope_prefix: str,
             frame: Pose, parts: Parts) -> Scope:
    """Links, joints and plugins of `model` and its nested models, posed in the top frame."""
    check_children(model, context)
    nested: dict[str, tuple[Element, Origin, Element]] = {}
    for child in model.children:
        if child.tag == "model":
            nested[child.get("name", "")] = (child, origin, child)
        elif child.tag == "include":
            included, where = context.include(child, origin)
            nested[child.value("name") or included.get("name", "")] = (included, where, child)
    scope = Scope.of(model, {n: placed for n, (_, _, placed) in nested.items()})
    for link in model.findall("link"):
        link_name = scope_prefix + link.get("name", "")
        if link_name in parts.links:
            raise link.error(f"two links named '{link_name}' in model "
                             f"'{model.get('name', '')}'")
        parts.links[link_name] = Link(link_name, link, frame * scope.resolve(link.get("name", "")),
                                      scope, frame, origin)
        if parts.first_link is None:
            parts.first_link = link_name
    parts.plugins += plugin_configs(model)
    for nested_name, (element, where, placed) in nested.items():
        if placed.tag == "include":
            parts.plugins += plugin_configs(placed)
        with context.inside(where):
            scope.nested[nested_name] = _collect(element, where, context,
                                                 f"{scope_prefix}{nested_name}::",
                                                 frame * scope.resolve(nested_name), parts)
    for joint in model.findall("joint"):
        parts.joints.append(_joint(joint, scope, scope_prefix, frame, origin))
    return scope


def _joint(joint: Element, scope: Scope, prefix: str, frame: Pose, origin: Origin) -> Joint:
    name, kind = joint.get("name", ""), joint.get("type", "")
    if kind not in JOINTS:
        raise joint.error(f"joint '{name}': unknown type '{kind}'"
                          f"{did_you_mean(kind, list(JOINTS))}; expected one of "
                          f"{', '.join(JOINTS)}")
    parent, child = joint.value("parent"), joint.value("child")
    if not parent or not child:
        raise joint.error(f"joint '{name}' needs <parent> and <child>")
    links = [n for n, (element, _) in scope.frames.items() if element.tag == "link"]
    if "::" not in child and child not in links:
        raise joint.error(f"joint '{name}': child link '{child}' does not exist in model "
                          f"'{scope.element.get('name', '')}'{did_you_mean(child, links)} "
                          f"(links: {', '.join(links)})")
    pose = scope.resolve(name)
    axes = []
    for tag in ("axis", "axis2")[:max(JOINTS[kind], 0)]:
        axes.append(_axis(joint, tag, scope, pose, origin))
    full_parent = "world" if parent == "world" else prefix + parent
    return Joint(prefix + name, joint, kind, full_parent, prefix + child, frame * pose,
                 [rotate(frame.quat, a) for a in axes])


def _axis(joint: Element, tag: str, scope: Scope, pose: Pose,
          origin: Origin) -> tuple[float, float, float]:
    axis = joint.find(tag)
    xyz_element = axis.find("xyz") if axis is not None else None
    xyz = numbers(xyz_element, 3, "an axis 'x y z'") if xyz_element is not None else [0, 0, 1]
    length = math.sqrt(sum(v * v for v in xyz))
    if length < 1e-12:
        raise (xyz_element or joint).error(f"joint '{joint.get('name')}': the axis is zero")
    vector = (xyz[0] / length, xyz[1] / length, xyz[2] / length)
    if xyz_element is not None and xyz_element.get("expressed_in"):
        return rotate(scope.resolve(xyz_element.get("expressed_in", ""), xyz_element).quat,
                      vector)
    in_model = origin.version < (1, 5) or (
        origin.version < (1, 7) and axis is not None and _flag(axis, "use_parent_model_frame"))
    return vector if in_model else rotate(pose.quat, vector)


def _tree(parts: Parts, model: Element) -> dict[str, Joint]:
    """child link -> its joint; every name checked, one parent per link, no loops."""
    parents: dict[str, Joint] = {}
    links = list(parts.links)
    for joint in parts.joints:
        for role, link in (("parent", joint.parent), ("child", joint.child)):
            if link not in parts.links and not (role == "parent" and link == "world"):
                raise joint.element.error(
                    f"joint '{joint.name}': {role} link '{link}' does not exist in model "
                    f"'{model.get('name', '')}'{did_you_mean(link, links)} (links: "
                    f"{', '.join(links)})")
        if joint.child in parents:
            raise joint.element.error(f"link '{joint.child}' has two parent joints "
                                      f"('{parents[joint.child].name}' and '{joint.name}')")
        parents[joint.child] = joint
    for start in parents:
        seen, link = {start}, start
        while link in parents and parents[link].parent != "world":
            link = parents[link].parent
            if link in seen:
                raise parents[start].element.error(f"the joints of model "
                                                   f"'{model.get('name', '')}' form a loop "
                                                   f"through link '{link}'")
            seen.add(link)
    return parents


def _canonical(model: Element, parts: Parts) -> str:
    named = model.get("canonical_link")
    if named:
        if named not in parts.links:
            raise model.error(f"canonical_link '{named}' is not a link of model "
                              f"'{model.get('name')}'{did_you_mean(named, list(parts.links))}")
        return named
    return parts.first_link or next(iter(parts.links))


class _Builder:
    def __init__(self, spec: Any, context: Context, prefix: str, static: bool, parts: Parts,
                 children: dict[str, list[Joint]]) -> None:
        self.spec, self.context, self.prefix = spec, context, prefix
        self.static, self.parts, self.children = static, parts, children

    def body(self, parent: Any, link: Link, local: Pose, joint: Joint | None) -> None:
        """The body of `link` at `local` in `parent`, its joint, geoms and child links."""
        check_children(link.element, self.context)
        body = parent.add_body()  # attributes one by one: faster than keywords
        body.name, body.pos, body.quat = self.prefix + link.name, local.pos, local.quat
        if not self.static:
            if joint is None:
                body.add_freejoint()
            else:
                self._joint(body, joint, link)
        if (link.element.value("gravity", "true") or "").lower() in ("false", "0"):
            body.gravcomp = 1.0
        self._geoms(body, link)
        set_inertial(body, link.element, self.static)
        for child_joint in self.children.get(link.name, []):
            child = self.parts.links[child_joint.child]
            self.body(body, child, link.pose.inverse() * child.pose, child_joint)

    def _joint(self, body: Any, joint: Joint, link: Link) -> None:
        """`joint` in the frame of its child `body` (whose pose in the model is link.pose)."""
        kind = joint.kind
        if kind in ("fixed", "gearbox"):
            if kind == "gearbox":
                self.context.warn(joint.element, f"joint '{joint.name}' (gearbox) is not "
                                                 "simulated: it is held fixed")
            return
        to_body = link.pose.inverse()
        pos = list((to_body * joint.pose).pos)
        if kind == "ball":
            body.add_joint(name=self.prefix + joint.name, type=mujoco.mjtJoint.mjJNT_BALL,
                           pos=pos)
            return
        if kind == "screw":
            self.context.warn(joint.element, f"joint '{joint.name}' (screw) turns without "
                                             "sliding: MuJoCo has no screw joint")
        names = [joint.name] if len(joint.axes) == 1 else [joint.name, f"{joint.name}::axis2"]
        for index, (axis, name) in enumerate(zip(joint.axes, names, strict=True)):
            tag = "axis" if index == 0 else "axis2"
            jtype = mujoco.mjtJoint.mjJNT_SLIDE if kind == "prismatic" else \
                mujoco.mjtJoint.mjJNT_HINGE
            added = body.add_joint(name=self.prefix + name, type=jtype, pos=pos,
                                   axis=list(rotate(to_body.quat, axis)))
            _limits(added, joint.element.find(tag), kind == "continuous")

    def _geoms(self, body: Any, link: Link) -> None:
        seen: set[str] = set()
        resolver = self._mesh_resolver(link)
        for tag in ("collision", "visual"):
            for element in link.element.iterfind(tag):
                local = self._local_pose(element, link)
                name = f"{self.prefix}{link.name}/{tag}/{element.get('name', '')}"
                geometry.add_geom(body, self.spec, element, local, tag == "visual",
                                  self.context.warn, resolver, name if name not in seen else "")
                seen.add(name)

    def _local_pose(self, element: Element, link: Link) -> Pose:
        pose = element.find("pose")
        if pose is None or not pose.get("relative_to"):
            return parse_pose(pose)
        in_model = link.frame * link.scope.pose_of(element, link.element.get("name", ""))
        return link.pose.inverse() * in_model

    def _mesh_resolver(self, link: Link) -> Any:
        def resolve(uri: str, element: Element) -> Any:
            return self.context.resolve(uri, element, link.origin, "mesh")
        return resolve


def _limits(joint: Any, axis: Element | None, continuous: bool) -> None:
    dynamics = axis.find("dynamics") if axis is not None else None
    if dynamics is not None:
        for tag, attribute in (("damping", "damping"), ("friction", "frictionloss"),
                               ("spring_stiffness", "stiffness")):
            value = dynamics.find(tag)
            if value is not None and value.stripped:
                _set(joint, attribute, max(number(value), 0.0))
        reference = dynamics.find("spring_reference")
        if reference is not None and reference.stripped:
            _set(joint, "springref", number(reference))
    limit = axis.find("limit") if axis is not None else None
    if limit is None or continuous:
        return
    low, high = (_bound(limit, tag) for tag in ("lower", "upper"))
    if low is not None and high is not None and -UNLIMITED < low <= high < UNLIMITED:
        joint.limited = mujoco.mjtLimited.mjLIMITED_TRUE
        joint.range = [low, high]
    effort = _bound(limit, "effort")
    if effort is not None and 0 < effort < UNLIMITED:
        joint.actfrclimited = mujoco.mjtLimited.mjLIMITED_TRUE
        joint.actfrcrange = [-effort, effort]


def _set(joint: Any, attribute: str, value: float) -> None:
    """MuJoCo 4 keeps some joint coefficients as arrays (the first is the linear one)."""
    current = getattr(joint, attribute)
    if hasattr(current, "__len__"):
        current[0] = value
    else:
        setattr(joint, attribute, value)


def _bound(limit: Element, tag: str) -> float | None:
    element = limit.find(tag)
    if element is None or not element.stripped:
        return None
    return number(element)
