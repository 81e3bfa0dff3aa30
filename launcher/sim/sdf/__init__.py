"""SDF (1.4 to 1.11), Gazebo's world and model format, built into MuJoCo through MjSpec.

`load_world` reads a `<world>` file; `load_model` reads a `<model>` to spawn. The modules:
xmltree (XML with places), pose, frames (relative_to), context (URIs, includes, versions,
warnings), elements (what is read or reported), geometry, inertial, model, world.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco

from launcher.sim.sdf.context import Context, Origin, read
from launcher.sim.sdf.model import BuiltModel, build
from launcher.sim.sdf.pose import IDENTITY, Pose, parse_pose
from launcher.sim.sdf.world import SdfWorld, load_world
from launcher.sim.sdf.xmltree import SdfError


@dataclass
class SdfModel:
    spec: Any
    model: BuiltModel
    pose: Pose  # the model's own <pose>, used when a spawn gives none
    warnings: list[str] = field(default_factory=list)


def load_model(text: str, path: Path | None, environ: Mapping[str, str] | None = None,
               packages: Any = None) -> SdfModel:
    label = str(path) if path else "<string>"
    root, version = read(text, label)
    element = root.find("model")
    if element is None:
        found = root.find("world")
        hint = " (this is a world: run it with `gz sim`)" if found is not None else ""
        raise root.error(f"no <model> to spawn in this SDF{hint}")
    context = Context(environ, packages)
    spec = mujoco.MjSpec()
    spec.modelname = element.get("name", "model")
    built = build(spec, element, Origin(path, version), context, "", IDENTITY)
    return SdfModel(spec, built, parse_pose(element.find("pose")), context.warnings)


__all__ = ["SdfError", "SdfModel", "SdfWorld", "load_model", "load_world", "Pose"]
