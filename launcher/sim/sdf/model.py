"""One SDF `<model>` (nested models and includes flattened into it) as MuJoCo bodies.

Links become bodies named `<prefix><link>` (nested: `<prefix>inner::link`), built as the tree
their joints make; a link without a parent joint is a root: it gets a free joint unless the
model is static, and a joint whose parent is `world` attaches it to the world. parts.py reads
the model, bodies.py builds it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import mujoco

from launcher.sim.sdf.bodies import Builder
from launcher.sim.sdf.context import Context, Origin
from launcher.sim.sdf.parts import Joint, Parts, canonical_link, collect, flag, tree
from launcher.sim.sdf.pose import IDENTITY, Pose
from launcher.sim.sdf.xmltree import Element


@dataclass
class BuiltModel:
    name: str
    root: str  # the body of the canonical link's tree (prefixed)
    offset: Pose  # that body's pose in the model frame
    roots: list[str]  # every root body (prefixed)
    static: bool
    plugins: list[Any]
    pose: Pose  # the model frame in the world


def new_spec(name: str) -> Any:
    """An empty MuJoCo spec for an SDF world or model: its name, and angles in radians as SDF
    gives them (joint limits)."""
    spec = mujoco.MjSpec()
    spec.modelname = name
    spec.compiler.degree = False
    return spec


def build(spec: Any, model: Element, origin: Origin, context: Context, prefix: str,
          placement: Pose, static: bool | None = None, name: str | None = None) -> BuiltModel:
    """Add `model` to `spec` under its world body at `placement` (the model frame); `name`
    overrides the model's own (an `<include>`'s `<name>`)."""
    name = name or model.get("name", "")
    if not name:
        raise model.error("<model> needs a name")
    is_static = static if static is not None else flag(model, "static")
    parts = Parts()
    with context.inside(origin):
        collect(model, origin, context, "", IDENTITY, parts)
    if not parts.links:
        raise model.error(f"model '{name}' has no <link>")
    parents = tree(parts, model)
    canonical = canonical_link(model, parts)
    roots = [link for link in parts.links if link not in parents or
             parents[link].parent == "world"]
    children: dict[str, list[Joint]] = {}
    for joint in parents.values():
        children.setdefault(joint.parent, []).append(joint)
    builder = Builder(spec, context, prefix, is_static, parts, children)
    for link in roots:
        builder.body(spec.worldbody, parts.links[link], placement * parts.links[link].pose,
                     parents.get(link))
    root = canonical
    while root in parents and parents[root].parent != "world":
        root = parents[root].parent
    return BuiltModel(name, prefix + root, parts.links[root].pose, [prefix + r for r in roots],
                      is_static, parts.plugins, placement)
