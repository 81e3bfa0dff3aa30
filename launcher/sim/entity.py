"""An entity of the world: a model of the world file (an SDF `<model>`, an MJCF top-level
body) or one spawned, as the rest of the sim knows it: its name, the bodies it roots, where its
model frame is, its plugins, and the ids bound to the current model."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from launcher.errors import LaunchError
from launcher.sim.plugins import Plugin
from launcher.sim.transform import IDENTITY, Pose


class SpawnError(LaunchError):
    """An entity cannot be added, found, moved or given that velocity."""


class NameInvalid(SpawnError):
    """A name that cannot name an entity."""


class NameTaken(SpawnError):
    """A name another entity has (and no renaming allowed)."""


@dataclass
class Spawn:
    """One request to add an entity: a template (templates.py) at a pose (w, x, y, z)."""
    template: Any
    name: str
    position: Sequence[float]
    quat: Sequence[float]
    allow_renaming: bool = False
    joints: Mapping[str, float] | None = None
    keyframe: str = ""  # an MJCF description's <key> its joints start from and reset to
    namespace: str = ""  # its ROS plugins' names go under it (entity_namespace)


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
    spawned: bool = False  # added while the sim runs (not a model of the world file)
    static: bool = False  # Gazebo's <static>: it never moves (one held by a joint may)
    start: dict[str, list[float]] = field(default_factory=dict)  # joint -> qpos, its keyframe
    info: Any = None  # what simulation_interfaces' SetEntityInfo gave it (category, tags, …)
