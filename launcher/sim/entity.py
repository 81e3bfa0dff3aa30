"""An entity of the world: a model of the world file (an SDF `<model>`, an MJCF top-level
body) or one spawned, as the rest of the sim knows it: its name, the bodies it roots, where its
model frame is, its plugins, and the ids bound to the current model."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from launcher.errors import LaunchError
from launcher.sim.plugins import Plugin
from launcher.sim.transform import IDENTITY, Pose


class SpawnError(LaunchError):
    """An entity cannot be added, found, moved or given that velocity."""


@dataclass
class Entity:
    name: str
    anchors: list[Any]  # what removing it deletes from the spec: its frame or root bodies
    root: str  # its root body, prefixed
    label: str  # where its description came from
    plugins: list[Plugin] = field(default_factory=list)
    offset: Pose = IDENTITY  # the root body's pose in the model frame
    roots: list[str] = field(default_factory=list)  # every root body (several trees)
    body: int = -1  # bound after each recompile
    qpos: int = -1  # address of its free joint's qpos, -1 if none
    dof: int = -1
    placed: dict[str, Pose] = field(default_factory=dict)  # static roots as loaded
