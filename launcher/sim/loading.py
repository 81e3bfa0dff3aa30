"""A world file, SDF or MJCF, into what the World is made from.

The format is the file's: `<sdf>` (Gazebo's `.sdf`/`.world`) or `<mujoco>` (MJCF; `.j2`
templates are rendered first). SDF models become the world's entities one for one; an MJCF
world's top-level bodies do.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launcher.sim import mjcf, sdf
from launcher.sim.mjcf import PluginConfig
from launcher.sim.plugins import mjcf_sensors
from launcher.sim.sdf.xmltree import after_prologue
from launcher.sim.transform import IDENTITY, Pose
from launcher.user_files import read_text


@dataclass
class WorldModel:
    """A model of the world file: what the loader built into the world's spec."""

    name: str
    root: str
    roots: list[str]
    offset: Pose = IDENTITY
    plugins: list[PluginConfig] = field(default_factory=list)
    static: bool = False  # an SDF <static> model; an MJCF body with no joint in it


@dataclass
class LoadedWorld:
    spec: Any
    label: str
    plugins: list[PluginConfig]
    models: list[WorldModel] | None  # None: the spec's top-level bodies
    real_time_factor: float | None = None
    warnings: list[str] = field(default_factory=list)
    spherical_coordinates: Any = None  # an SDF world's (navsat reads it)


def load_world_file(path: Path, values: Mapping[str, str] | None = None,
                    environ: Mapping[str, str] | None = None,
                    as_written: bool = False) -> LoadedWorld:
    """`as_written`: an MJCF as mujoco_ros2_control loads it, compiled with MuJoCo's own
    defaults (mjcf.compile_spec) and its sensors left to its hardware; else its sensors are
    on ROS (sim/plugins/mjcf_sensors.py)."""
    text = read_text(path)
    if path.name.endswith(".j2"):
        text = mjcf.render_template(text, path, values or {})
    if after_prologue(text).startswith("<sdf"):
        return _from_sdf(sdf.load_world(text, path, environ), path)
    source = mjcf.read(text, path, environ=environ, rendered=True)
    if not as_written:  # (mujoco_ros2_control's hardware reads its sensors itself)
        source.plugins.extend(mjcf_sensors.configs(source.label))
    return LoadedWorld(mjcf.compile_spec(source, as_written), str(path), source.plugins,
                       None)


def _from_sdf(world: sdf.SdfWorld, path: Path) -> LoadedWorld:
    models = [WorldModel(m.name, m.root, m.roots, m.offset, m.plugins, m.static)
              for m in world.models]
    return LoadedWorld(world.spec, str(path), world.plugins, models, world.real_time_factor,
                       world.warnings, world.spherical_coordinates)
