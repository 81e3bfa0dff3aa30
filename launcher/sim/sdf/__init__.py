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

from launcher.sim.sdf.context import opened
from launcher.sim.sdf.model import BuiltModel, build, new_spec
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
    element, origin, context = opened(text, path, "model", " to spawn (a <world> file is run "
                                      "with `gz sim`)", environ, packages)
    spec = new_spec(element.get("name", "model"))
    built = build(spec, element, origin, context, "", IDENTITY)
    return SdfModel(spec, built, parse_pose(element.find("pose")), context.warnings)


__all__ = ["SdfError", "SdfModel", "SdfWorld", "load_model", "load_world", "Pose"]
