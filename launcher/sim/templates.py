"""Robot and model descriptions (URDF, SDF or MJCF, a string or a file) parsed once into
templates.

A template is an MjSpec ready to be copied and attached, with its plugin configs. Templates
are cached by the description's text (files: by path and modification time), so spawning ten
copies of one robot parses it once.
"""

from __future__ import annotations

import hashlib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco

from launcher.errors import LaunchError
from launcher.sim import mjcf, sdf, urdf
from launcher.sim.mjcf import PluginConfig
from launcher.sim.plugins import mjcf_sensors
from launcher.sim.resources import model_file, resolve_uri
from launcher.sim.sdf.xmltree import after_prologue
from launcher.sim.transform import IDENTITY, Pose
from launcher.user_files import read_text


class UnsupportedFormat(LaunchError):
    """A description in none of the formats the sim reads."""


@dataclass
class Template:
    spec: mujoco.MjSpec
    name: str  # the description's own name (robot name= / model name= / mujoco model=)
    label: str
    plugins: list[PluginConfig] = field(default_factory=list)
    friction: dict[str, float] = field(default_factory=dict)
    root: str = ""  # the root body (default: the first)
    offset: Pose = IDENTITY  # the root body's pose in the model frame
    static: bool = False  # no free joint: the model never moves by itself
    pose: Pose = IDENTITY  # the description's own pose (SDF <model><pose>)
    warnings: list[str] = field(default_factory=list)


class Templates:
    """Templates of descriptions, each parsed once (cached by text, or by path and mtime)."""

    def __init__(self, packages: object | None = None,
                 environ: Mapping[str, str] | None = None) -> None:
        self._cache: dict[str, Template] = {}
        self.packages, self.environ = packages, environ

    def from_string(self, text: str, label: str = "<string>") -> Template:
        key = hashlib.sha1(text.encode()).hexdigest()
        if key not in self._cache:
            self._cache[key] = self._parse(text, label, None)
        return self._cache[key]

    def from_file(self, uri: str) -> Template:
        path = resolve_uri(uri, None, self.packages, self.environ)
        if path.is_dir():  # model://name gives the folder's model file already; a plain folder
            path = model_file(path)
        stat = path.stat()
        key = f"{path}:{stat.st_mtime_ns}:{stat.st_size}"
        if key not in self._cache:
            self._cache[key] = self._parse(read_text(path), str(path), path)
        return self._cache[key]

    def _parse(self, text: str, label: str, path: Path | None) -> Template:
        stripped = after_prologue(text)
        if not stripped:
            raise LaunchError(f"{label}: the description is empty")
        if stripped.startswith("<robot"):
            prepared = urdf.prepare(text, label, path.parent if path else None, self.packages,
                                    self.environ)
            spec = _spec_from(prepared.text, label)
            for config, pose in prepared.sensors:  # a site at each sensor's pose on its link
                site = spec.body(config.link).add_site(name=config.site, group=5)
                site.pos, site.quat = list(pose.pos), list(pose.quat)
            static = prepared.root_link == "world"
            if static:  # a root link named "world" anchors the robot, as in Gazebo
                _exclude_anchored_parents(spec)
            return Template(spec, prepared.name, label,
                            [*prepared.plugins, *(c for c, _ in prepared.sensors)],
                            prepared.friction, static=static,
                            warnings=prepared.warnings)
        if stripped.startswith("<mujoco"):
            source = mjcf.read(text, path, environ=self.environ)
            spec = mjcf.compile_spec(source)
            return Template(spec, spec.modelname or "model", label,
                            [*source.plugins, *mjcf_sensors.configs(label)])
        if stripped.startswith("<sdf"):
            loaded = sdf.load_model(text, path, self.environ, self.packages)
            model = loaded.model
            return Template(loaded.spec, model.name, label, model.plugins, root=model.root,
                            offset=model.offset, static=model.static, pose=loaded.pose,
                            warnings=loaded.warnings)
        raise UnsupportedFormat(f"{label}: not a model description: expected URDF (<robot>), SDF "
                          f"(<sdf>) or MJCF (<mujoco>), found '{stripped[:40]}'")


def _exclude_anchored_parents(spec: Any) -> None:
    """MuJoCo never collides a body with its parent, except where the parent is welded to the
    world: a cart on a rail fixed to the `world` link would grind along it. Gazebo collides no
    two links of one model (self_collide off), so a moving link and the model's fixed links are
    excluded pairs, which restores the parent filter for the anchored part."""
    fixed, moving = [], []
    stack = list(spec.worldbody.bodies)
    while stack:
        body = stack.pop()
        if body.joints:
            moving.append(body.name)
        else:
            fixed.append(body.name)
            stack.extend(body.bodies)
    for child in moving:
        for parent in fixed:
            spec.add_exclude(bodyname1=parent, bodyname2=child)


def _spec_from(text: str, label: str) -> Any:
    try:
        return mujoco.MjSpec.from_string(text)
    except ValueError as exc:
        raise LaunchError(f"{label}: MuJoCo could not read the URDF: "
                          f"{' '.join(str(exc).split())}") from None
