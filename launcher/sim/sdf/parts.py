"""One SDF `<model>` read into parts: its links, joints and plugins, with nested models and
includes flattened in and every pose put in the model frame; the joint tree checked (names
that exist, one parent per link, no loops) and the canonical link chosen."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from launcher.errors import did_you_mean
from launcher.sim.sdf.context import Context, Origin
from launcher.sim.sdf.elements import check_children, plugin_configs
from launcher.sim.sdf.frames import Scope
from launcher.sim.sdf.pose import Pose, numbers, rotate
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


def flag(element: Element, tag: str) -> bool:
    return (element.value(tag, "false") or "").lower() in ("true", "1")


def collect(model: Element, origin: Origin, context: Context, scope_prefix: str,
             frame: Pose, parts: Parts) -> Scope:
    """Links, joints and plugins of `model` and its nested models, posed in the top frame."""
    check_children(model, context)
    nested: dict[str, tuple[Element, Origin, Element | None]] = {}  # model, origin, include
    merged: set[str] = set()  # the includes with merge="true"
    for child in model.children:
        if child.tag == "model":
            nested[child.get("name", "")] = (child, origin, None)
        elif child.tag == "include":
            included, where = context.include(child, origin)
            name = child.value("name") or included.get("name", "")
            nested[name] = (included, where, child)
            if (child.get("merge") or "").lower() in ("true", "1"):
                merged.add(name)
    # an include is placed by its own <pose>, else by the included model's
    scope = Scope.of(model, {n: include if include is not None and include.find("pose")
                             is not None else element
                             for n, (element, _, include) in nested.items()})
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
    for nested_name, (element, where, include) in nested.items():
        if include is not None:
            parts.plugins += plugin_configs(include)
        # a merged include's links, joints and plugins are the model's own: no scope prefix
        prefix = scope_prefix if nested_name in merged else f"{scope_prefix}{nested_name}::"
        with context.inside(where):
            scope.nested[nested_name] = collect(element, where, context, prefix,
                                                 frame * scope.resolve(nested_name), parts)
        if nested_name in merged:
            for name in scope.nested[nested_name].frames:
                scope.merged.setdefault(name, nested_name)
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
    links += [n for n, head in scope.merged.items()
              if scope.nested[head].frames[n][0].tag == "link"]
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
        origin.version < (1, 7) and axis is not None and flag(axis, "use_parent_model_frame"))
    return vector if in_model else rotate(pose.quat, vector)


def tree(parts: Parts, model: Element) -> dict[str, Joint]:
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


def canonical_link(model: Element, parts: Parts) -> str:
    named = model.get("canonical_link")
    if named:
        if named not in parts.links:
            raise model.error(f"canonical_link '{named}' is not a link of model "
                              f"'{model.get('name')}'{did_you_mean(named, list(parts.links))}")
        return named
    return parts.first_link or next(iter(parts.links))


