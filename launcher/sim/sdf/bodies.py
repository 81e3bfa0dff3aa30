"""The bodies of one SDF model in MjSpec: a link's body, its joint, geoms and inertia, and the
bodies of its child links, each in its parent's frame (joint frames and axes turned into the
child body's frame)."""

from __future__ import annotations

from typing import Any

import mujoco

from launcher.sim.plugins import canonical
from launcher.sim.plugins.label import VisualLabel
from launcher.sim.sdf.context import Context
from launcher.sim.sdf.elements import check_children, plugin_configs
from launcher.sim.sdf.geometry import add_geom
from launcher.sim.sdf.inertial import set_inertial
from launcher.sim.sdf.parts import UNLIMITED, Joint, Link, Parts
from launcher.sim.sdf.pose import Pose, number, parse_pose, rotate
from launcher.sim.sdf.xmltree import Element
from launcher.sim.sensors.config import sensor_config


class Builder:
    def __init__(self, spec: Any, context: Context, prefix: str, static: bool, parts: Parts,
                 children: dict[str, list[Joint]]) -> None:
        self.spec, self.context, self.prefix = spec, context, prefix
        self.static, self.parts, self.children = static, parts, children
        self.sensor_sites: set[str] = set()

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
        self._sensors(body, link)
        if joint is not None:
            self._joint_sensors(body, joint, link)
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
                add_geom(body, self.spec, element, local, tag == "visual",
                                  self.context.warn, resolver, name if name not in seen else "")
                seen.add(name)
                if tag == "visual":
                    self._visual_plugins(element, name[len(self.prefix):])

    def _visual_plugins(self, element: Any, geom: str) -> None:
        """A `<visual>`'s plugins: gz-sim-label-system labels that visual alone; Gazebo's
        visual plugins (shaders, LEDs) draw nothing here and are a warning."""
        for config in plugin_configs(element):
            if canonical(config.filename) == "gz-sim-label-system" or \
                    canonical(config.name) == "gz::sim::systems::Label":
                self.parts.plugins.append(VisualLabel(config.filename, config.name,
                                                      config.element, config.where,
                                                      visual=geom))
            else:
                self.context.warn(config.element, f"visual plugin '{config.filename}' draws "
                                  "nothing in launcher's renderer; it is ignored")

    def _sensors(self, body: Any, link: Link) -> None:
        """Each `<sensor>` of the link: a site at its pose (hidden, group 5), and its config
        among the model's plugins."""
        for element in link.element.iterfind("sensor"):
            config = sensor_config(element, link.name, self.context.warn)
            if config is None:
                continue
            if config.site in self.sensor_sites:
                raise element.error(f"two sensors named '{config.name}' in link '{link.name}'")
            self.sensor_sites.add(config.site)
            local = self._local_pose(element, link)
            site = body.add_site()
            site.name, site.pos, site.quat, site.group = self.prefix + config.site, \
                local.pos, local.quat, 5
            self.parts.plugins.append(config)

    def _joint_sensors(self, body: Any, joint: Joint, link: Link) -> None:
        """Each `<sensor>` of a joint (force_torque): a site on the child's body at the
        joint's frame and the sensor's pose in it."""
        for element in joint.element.iterfind("sensor"):
            config = sensor_config(element, link.name, self.context.warn, joint=joint.name)
            if config is None:
                continue
            if config.site in self.sensor_sites:
                raise element.error(f"two sensors named '{config.name}' in joint "
                                    f"'{joint.name}'")
            self.sensor_sites.add(config.site)
            local = link.pose.inverse() * joint.pose * parse_pose(element.find("pose"))
            site = body.add_site()
            site.name, site.pos, site.quat, site.group = self.prefix + config.site, \
                local.pos, local.quat, 5
            self.parts.plugins.append(config)

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
