"""Plugins: systems attached to the world or to one entity, as Gazebo's are.

A plugin is named by its `filename` (and `name`) as in Gazebo:
  * built-in robot systems, under their Gazebo names or a short one (BUILTIN below);
  * Python plugins: `filename="my_plugin.py"` (or `my_plugin`) found in a folder of
    MUJOCO_SIM_PLUGIN_PATH, the class named by `name`; or `filename="package.module"` with the
    class in `name`, imported as a module.
The sim calls, in order: `prepare(spec)` (entity plugins, before attaching: add actuators),
`load()` (after compiling: publishers, subscriptions), `bind(model, data)` after every
recompile, `pre_step` before each batch of steps, `post_step` after a batch once sim time has
reached the plugin's `next_update`, `reset()` on a world reset and `close()` when its entity
is removed. `next_update` lets the sim step in batches up to the next time a plugin must
run; leave it at 0.0 to run after every step. Publishers report `get_subscription_count()`:
skip building messages nobody receives.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
import os
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, did_you_mean
from launcher.sim.mjcf import PluginConfig

PLUGIN_PATH = "MUJOCO_SIM_PLUGIN_PATH"

BUILTIN = {
    "world_state": "launcher.sim.plugins.world_state:WorldState",
    "diff_drive": "launcher.sim.plugins.diff_drive:DiffDrive",
    "gz-sim-diff-drive-system": "launcher.sim.plugins.diff_drive:DiffDrive",
    "gz::sim::systems::DiffDrive": "launcher.sim.plugins.diff_drive:DiffDrive",
    "libgazebo_ros_diff_drive.so": "launcher.sim.plugins.diff_drive:DiffDrive",
    "joint_state_publisher": "launcher.sim.plugins.joint_state:JointStatePublisher",
    "gz-sim-joint-state-publisher-system": "launcher.sim.plugins.joint_state:JointStatePublisher",
    "gz::sim::systems::JointStatePublisher":
        "launcher.sim.plugins.joint_state:JointStatePublisher",
    "libgazebo_ros_joint_state_publisher.so":
        "launcher.sim.plugins.joint_state:JointStatePublisher",
    "joint_position_controller":
        "launcher.sim.plugins.joint_controller:JointPositionController",
    "gz-sim-joint-position-controller-system":
        "launcher.sim.plugins.joint_controller:JointPositionController",
    "gz::sim::systems::JointPositionController":
        "launcher.sim.plugins.joint_controller:JointPositionController",
    "joint_velocity_controller": "launcher.sim.plugins.joint_controller:JointVelocityController",
    "gz-sim-joint-controller-system":
        "launcher.sim.plugins.joint_controller:JointVelocityController",
    "gz::sim::systems::JointController":
        "launcher.sim.plugins.joint_controller:JointVelocityController",
}


class PluginError(LaunchError):
    pass


class Plugin:
    """Base class of every plugin; see the module text for when each hook runs."""

    next_update = 0.0

    def __init__(self, sim: Any, entity: Any, config: PluginConfig) -> None:
        self.sim, self.entity, self.config = sim, entity, config
        self.label = config.name or config.filename

    # --- hooks -----------------------------------------------------------------------------
    def prepare(self, spec: Any) -> None:
        pass

    def load(self) -> None:
        pass

    def bind(self, model: Any, data: Any) -> None:
        pass

    def pre_step(self, model: Any, data: Any) -> None:
        pass

    def post_step(self, model: Any, data: Any) -> None:
        pass

    def reset(self) -> None:
        pass

    def close(self) -> None:
        pass

    # --- configuration ---------------------------------------------------------------------
    def text(self, name: str, default: str | None = None) -> str | None:
        element = self.config.element.find(name)
        if element is None or element.text is None:
            return default
        return element.text.strip()

    def texts(self, name: str) -> list[str]:
        return [e.text.strip() for e in self.config.element.findall(name) if e.text]

    def number(self, name: str, default: float, low: float = -math.inf,
               high: float = math.inf) -> float:
        raw = self.text(name)
        if raw is None:
            return default
        try:
            value = float(raw)
        except ValueError:
            raise PluginError(f"{self.config.where}: plugin {self.label}: <{name}> must be a "
                              f"number, got '{raw}'") from None
        if not (low <= value <= high) or math.isnan(value):
            raise PluginError(f"{self.config.where}: plugin {self.label}: <{name}> must be in "
                              f"[{low}, {high}], got {value}")
        return value

    def topic(self, name: str | None, default: str) -> str:
        """Relative names live under the entity (`/model/<name>/…`), absolute ones as given."""
        name = name or default
        if name.startswith("/"):
            return name
        owner = f"/model/{self.entity.name}" if self.entity is not None else \
            f"/world/{self.sim.world_name}"
        return f"{owner}/{name}"


def find_class(config: PluginConfig, environ: dict[str, str] | None = None) -> type[Plugin]:
    """The plugin class a config names (see the module text)."""
    env = os.environ if environ is None else environ
    target = BUILTIN.get(config.filename) or BUILTIN.get(config.name)
    if target is not None:
        module_name, _, attribute = target.partition(":")
        return getattr(importlib.import_module(module_name), attribute)
    stem = config.filename.removesuffix(".py")
    folders = [Path(p) for p in env.get(PLUGIN_PATH, "").split(os.pathsep) if p]
    for folder in folders:
        path = folder / f"{stem}.py"
        if path.is_file():
            return _class_from(_load_file(path, config), config, str(path))
    if stem and all(part.isidentifier() for part in stem.split(".")) and "." in stem:
        try:
            module = importlib.import_module(stem)
        except ImportError:
            module = None
        if module is not None:
            return _class_from(module, config, stem)
    where = ", ".join(str(f) for f in folders) or f"{PLUGIN_PATH} is not set"
    raise PluginError(f"{config.where}: unknown plugin '{config.filename}' (name "
                      f"'{config.name}'): not a built-in system and no {stem}.py in {where}"
                      f"{did_you_mean(config.filename, list(BUILTIN))}")


def _load_file(path: Path, config: PluginConfig) -> Any:
    spec = importlib.util.spec_from_file_location(f"mujoco_sim_plugin_{path.stem}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except Exception as exc:
        raise PluginError(f"{config.where}: plugin {path} failed to import: "
                          f"{type(exc).__name__}: {exc}") from None
    return module


def _class_from(module: Any, config: PluginConfig, where: str) -> type[Plugin]:
    found = getattr(module, config.name, None)
    if isinstance(found, type):
        return found
    classes = [n for n, v in vars(module).items() if isinstance(v, type) and
               issubclass(v, Plugin) and v is not Plugin]
    raise PluginError(f"{config.where}: {where} has no class '{config.name}'"
                      f"{did_you_mean(config.name, classes)}")


def config_from(xml: str, where: str = "<plugin>") -> PluginConfig:
    element = ET.fromstring(xml)
    return PluginConfig(element.get("filename", ""), element.get("name", ""), element, where)
