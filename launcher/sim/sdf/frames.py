"""SDF's frame semantics inside one model: every named frame's pose in the model frame.

Links, joints, `<frame>`s and nested models are frames. A pose is relative to the frame its
`relative_to` names, or by default: links and nested models to the model (`__model__`),
joints to their child link, frames to what they are `attached_to`. Names may be scoped
(`inner::link`). SDF before 1.7 has no `relative_to`; its defaults are the same.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from launcher.errors import did_you_mean
from launcher.sim.sdf.pose import IDENTITY, Pose, parse_pose
from launcher.sim.sdf.xmltree import Element

MODEL_FRAME = "__model__"


@dataclass
class Scope:
    """The frames of one model element; nested models are scopes of their own."""

    element: Element
    frames: dict[str, tuple[Element, str]] = field(default_factory=dict)  # name -> (el, default)
    nested: dict[str, Scope] = field(default_factory=dict)
    # frames of a `merge="true"` include: their own names, found in the include's scope
    merged: dict[str, str] = field(default_factory=dict)  # frame -> the include's name
    _resolved: dict[str, Pose] = field(default_factory=dict)
    _resolving: set[str] = field(default_factory=set)

    @classmethod
    def of(cls, model: Element, nested: dict[str, Element]) -> Scope:
        """`nested` maps the names of nested models (inline or included) to their elements."""
        scope = cls(model)
        for link in model.findall("link"):
            scope.frames[link.get("name", "")] = (link, MODEL_FRAME)
        for joint in model.findall("joint"):
            scope.frames[joint.get("name", "")] = (joint, joint.value("child", "") or "")
        for frame in model.findall("frame"):
            scope.frames[frame.get("name", "")] = (frame, frame.get("attached_to") or MODEL_FRAME)
        for name, element in nested.items():
            scope.frames[name] = (element, MODEL_FRAME)
        return scope

    def resolve(self, name: str, asked_by: Element | None = None) -> Pose:
        """The pose of frame `name` in the model frame."""
        if name in ("", MODEL_FRAME):
            return IDENTITY
        if name in self._resolved:
            return self._resolved[name]
        if "::" in name:
            head, _, rest = name.partition("::")
            if head in self.nested:
                return self.resolve(head, asked_by) * self.nested[head].resolve(rest, asked_by)
        if name not in self.frames and name in self.merged:
            head = self.merged[name]
            return self.resolve(head, asked_by) * self.nested[head].resolve(name, asked_by)
        if name not in self.frames:
            where = asked_by or self.element
            model = self.element.get("name", "")
            raise where.error(f"unknown frame '{name}' in model '{model}'"
                              f"{did_you_mean(name, list(self.frames))}; frames: "
                              f"{', '.join(sorted(self.frames)) or 'none'}, {MODEL_FRAME}")
        if name in self._resolving:
            raise self.frames[name][0].error(f"the poses of frame '{name}' form a cycle of "
                                             "relative_to references")
        self._resolving.add(name)
        element, default = self.frames[name]
        pose = self.pose_of(element, default)
        self._resolving.discard(name)
        self._resolved[name] = pose
        return pose

    def pose_of(self, element: Element, default: str = MODEL_FRAME) -> Pose:
        """The pose of `element`'s own `<pose>` (or `<include>`'s) in the model frame."""
        pose_element = element.find("pose")
        relative_to = default
        if pose_element is not None and pose_element.get("relative_to"):
            relative_to = pose_element.get("relative_to") or default
        if relative_to == element.get("name") and element.tag != "joint":
            raise element.error(f"<pose relative_to='{relative_to}'> names the element itself")
        base = self.resolve(relative_to, pose_element or element)
        return base * parse_pose(pose_element)
