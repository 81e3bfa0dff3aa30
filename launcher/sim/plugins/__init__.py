"""Plugins: systems attached to the world or to one entity, as Gazebo's are.

A plugin is named by its `filename` (and `name`) as in Gazebo:
  * built-in robot systems, under their Gazebo names (any spelling: `gz-sim-…-system`,
    `libgz-sim8-…-system.so`, `ignition-gazebo-…`, `gz::sim::systems::…`, `ignition::gazebo::…`)
    or a short one (BUILTIN below); classic gazebo_ros plugins in URDF (CLASSIC);
  * Gazebo's infrastructure systems (physics, user commands, scene broadcaster, sensors …),
    which the sim is by itself: accepted and nothing loaded;
  * Python plugins: `filename="my_plugin.py"` (or `my_plugin`) found in a folder of
    MUJOCO_SIM_PLUGIN_PATH, GZ_SIM_SYSTEM_PLUGIN_PATH or GAZEBO_PLUGIN_PATH, the class named by
    `name`; or `filename="package.module"` with the class in `name`, imported as a module.
A C++ library (`….so`) or a Gazebo system launcher does not have is one warning: the world
runs without it.
The sim calls, in order: `prepare(spec)` (entity plugins, before compiling: add actuators;
the entity's names in `spec` carry `spec_prefix`, empty for a spawned description and
`<entity>/` for a model of the world file: use `joint_names(spec)` and `in_spec(name)`),
`load()` (after compiling: publishers, subscriptions), `bind(model, data)` after every
recompile, `pre_step` before each batch of steps, `post_step` after a batch once sim time has
reached the plugin's `next_update`, `paused(model, data)` some 20 times a second while the
world is paused (Gazebo runs its systems' PostUpdate paused too), `reset()` on a world reset
and `close()` when its entity is removed. `next_update` lets the sim step in batches up to
the next time a plugin must run; leave it at 0.0 to run after every step. Publishers report
`get_subscription_count()`: skip building messages nobody receives.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
import os
import re
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any, TypeVar

from launcher.errors import LaunchError, ParseError, did_you_mean
from launcher.schema import Attr, Kind, build, value_of
from launcher.sim.mjcf import PluginConfig

R = TypeVar("R")

PLUGIN_PATH = "MUJOCO_SIM_PLUGIN_PATH"
PLUGIN_VARIABLES = (PLUGIN_PATH, "GZ_SIM_SYSTEM_PLUGIN_PATH", "IGN_GAZEBO_SYSTEM_PLUGIN_PATH",
                    "GAZEBO_PLUGIN_PATH")
# Gazebo systems that are the sim itself, or feed sensors launcher reports on its own
INFRASTRUCTURE = {"physics", "user-commands", "scene-broadcaster", "sensors", "imu",
                  "contact", "altimeter", "air-pressure", "magnetometer", "navsat",
                  "forcetorque", "air-speed", "cpu-lidar", "logical-camera", "log", "wind-effects"}
_GZ_FILE = re.compile(
    r"^(?:lib)?(?:gz-sim|ignition-gazebo)\d*-(?P<system>.+?)-system(?:\.so)?$")
_GZ_CLASS = re.compile(r"^(?:gz::sim|ignition::gazebo)::systems::(?P<system>\w+)$")

BUILTIN = {
    "world_state": "launcher.sim.plugins.world_state:WorldState",
    "mujoco.plugin.lidar": "launcher.sim.plugins.mjcf_lidar:MjcfLidar",
    "mjcf_sensors": "launcher.sim.plugins.mjcf_sensors:MjcfSensors",
    "mjcf_cameras": "launcher.sim.plugins.mjcf_cameras:MjcfCameras",
    "diff_drive": "launcher.sim.plugins.diff_drive:DiffDrive",
    "gz-sim-diff-drive-system": "launcher.sim.plugins.diff_drive:DiffDrive",
    "gz::sim::systems::DiffDrive": "launcher.sim.plugins.diff_drive:DiffDrive",
    "joint_state_publisher": "launcher.sim.plugins.joint_state:JointStatePublisher",
    "gz-sim-joint-state-publisher-system": "launcher.sim.plugins.joint_state:JointStatePublisher",
    "gz-sim-label-system": "launcher.sim.plugins.label:Label",
    "gz::sim::systems::Label": "launcher.sim.plugins.label:Label",
    "gz::sim::systems::JointStatePublisher":
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
    "gz-sim-ackermann-steering-system": "launcher.sim.plugins.ackermann:AckermannSteering",
    "gz::sim::systems::AckermannSteering": "launcher.sim.plugins.ackermann:AckermannSteering",
    "gz-sim-linearbatteryplugin-system": "launcher.sim.plugins.battery:LinearBattery",
    "gz-sim-linear-battery-plugin-system": "launcher.sim.plugins.battery:LinearBattery",
    "gz::sim::systems::LinearBatteryPlugin": "launcher.sim.plugins.battery:LinearBattery",
    "gz-sim-joint-trajectory-controller-system":
        "launcher.sim.plugins.gz_trajectory:JointTrajectoryController",
    "gz::sim::systems::JointTrajectoryController":
        "launcher.sim.plugins.gz_trajectory:JointTrajectoryController",
    "gz-sim-triggered-publisher-system": "launcher.sim.plugins.triggered:TriggeredPublisher",
    "gz::sim::systems::TriggeredPublisher": "launcher.sim.plugins.triggered:TriggeredPublisher",
    "gz-sim-apply-joint-force-system": "launcher.sim.plugins.motion:ApplyJointForce",
    "gz::sim::systems::ApplyJointForce": "launcher.sim.plugins.motion:ApplyJointForce",
    "gz-sim-velocity-control-system": "launcher.sim.plugins.motion:VelocityControl",
    "gz::sim::systems::VelocityControl": "launcher.sim.plugins.motion:VelocityControl",
    "gz-sim-odometry-publisher-system": "launcher.sim.plugins.pose_systems:OdometryPublisher",
    "gz::sim::systems::OdometryPublisher": "launcher.sim.plugins.pose_systems:OdometryPublisher",
    "gz-sim-pose-publisher-system": "launcher.sim.plugins.pose_systems:PosePublisher",
    "gz::sim::systems::PosePublisher": "launcher.sim.plugins.pose_systems:PosePublisher",
    "gz_ros2_control::GazeboSimROS2ControlPlugin":
        "launcher.sim.plugins.ros2_control:GzRos2Control",
    "ign_ros2_control::IgnitionROS2ControlPlugin":
        "launcher.sim.plugins.ros2_control:GzRos2Control",
    "gazebo_ros2_control::GazeboRosControlPlugin":
        "launcher.sim.plugins.ros2_control:GzRos2Control",
}
CLASSIC = {
    "gazebo_ros_diff_drive": "launcher.sim.plugins.classic:ClassicDiffDrive",
    "gazebo_ros_joint_state_publisher": "launcher.sim.plugins.classic:ClassicJointStates",
    "gazebo_ros_p3d": "launcher.sim.plugins.classic_state:P3D",
    "gazebo_ros_ft_sensor": "launcher.sim.plugins.classic_state:FTSensor",
    # gz_ros2_control's plugin, in its gz, ignition and classic spellings (lib…so stripped)
    "gz_ros2_control-system": "launcher.sim.plugins.ros2_control:GzRos2Control",
    "ign_ros2_control-system": "launcher.sim.plugins.ros2_control:GzRos2Control",
    "gazebo_ros2_control": "launcher.sim.plugins.ros2_control:GzRos2Control",
}


class PluginUnavailable(LaunchError):
    """A plugin launcher cannot run (a C++ library, a Gazebo system it lacks): a warning."""


class PluginError(LaunchError):
    pass


class Plugin:
    """Base class of every plugin; see the module text for when each hook runs."""

    next_update = 0.0
    spec_prefix = ""
    unknown_parameters = "warn"  # Gazebo ignores elements it does not know; launcher says so

    def __init__(self, sim: Any, entity: Any, config: PluginConfig) -> None:
        self.sim, self.entity, self.config = sim, entity, config
        self.label = config.name or config.filename
        self.warned: set[str] = set()  # (warn_once's keys)

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

    def paused(self, model: Any, data: Any) -> None:
        pass

    def reset(self) -> None:
        pass

    def close(self) -> None:
        pass

    # --- names in the spec given to prepare ------------------------------------------------
    def in_spec(self, name: str) -> str:
        return self.spec_prefix + name

    def joint_names(self, spec: Any, types: tuple[Any, ...] = ()) -> list[str]:
        """The entity's joints in `spec`, without the prefix (of `types` if given)."""
        prefix = self.spec_prefix
        return [j.name[len(prefix):] for j in spec.joints
                if j.name.startswith(prefix) and j.name != prefix and
                (not types or j.type in types)]

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
        """One number of the configuration (for plugins that do not declare theirs)."""
        raw = self.text(name)
        if raw is None:
            return default
        bounds = Attr(Kind.FLOAT, minimum=None if math.isinf(low) else low,
                      maximum=None if math.isinf(high) else high)
        try:
            return float(value_of(Kind.FLOAT, raw, f"<{name}>", bounds))
        except ParseError as exc:
            raise PluginError(f"{self.config.where}: plugin {self.label}: {exc.message}") \
                from None

    def three_numbers(self, tag: str, text: str) -> list[float]:
        """`<tag>`'s three numbers (a vector or angles), refused by name unless finite."""
        try:
            values = [float(v) for v in text.split()]
        except ValueError:
            values = []
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise PluginError(f"{self.config.where}: plugin {self.label}: <{tag}> expects "
                              f"three numbers, got '{text}'")
        return values

    def parameters(self, cls: type[R]) -> R:
        """The configuration's elements as a record of `cls`'s declared fields (a repeated
        element is a list); unknown elements are warned about (`unknown_parameters`)."""
        values: dict[str, Any] = {}
        for child in self.config.element:
            text = (child.text or "").strip()
            if child.tag in values:
                previous = values[child.tag]
                values[child.tag] = [*(previous if isinstance(previous, list) else [previous]),
                                     text]
            else:
                values[child.tag] = text
        try:
            return build(cls, values, f"{self.config.where}: plugin {self.label}",
                         unknown=self.unknown_parameters,
                         warn=self.sim.transport.logger.warning)
        except ParseError as exc:
            raise PluginError(exc.message) from None

    def warn_once(self, key: str, text: str) -> None:
        """Warn with `text` the first time `key` comes up only: a bad command sent every step
        would flood the log."""
        if key not in self.warned:
            self.warned.add(key)
            self.sim.transport.logger.warning(text)

    def topic(self, name: str | None, default: str) -> str:
        """Relative names live under the entity (`/model/<name>/…`), absolute ones as given."""
        name = name or default
        if name.startswith("/"):
            return name
        owner = f"/model/{self.entity.name}" if self.entity is not None else \
            f"/world/{self.sim.world_name}"
        return f"{owner}/{name}"


def canonical(name: str) -> str:
    """Gazebo's spellings of one system as its gz-sim name: `libignition-gazebo6-imu-system.so`
    and `ignition::gazebo::systems::Imu` are `gz-sim-imu-system` and `gz::sim::systems::Imu`."""
    found = _GZ_FILE.match(name)
    if found:
        return f"gz-sim-{found.group('system')}-system"
    found = _GZ_CLASS.match(name)
    if found:
        return f"gz::sim::systems::{found.group('system')}"
    return name


def systems_of(configs: Any) -> set[str]:
    """The canonical names of the systems among a world's plugins (what its sensors need)."""
    return {canonical(name) for config in configs for name in (config.filename, config.name)}


def is_infrastructure(config: PluginConfig) -> bool:
    found = _GZ_FILE.match(config.filename)
    return bool(found) and found.group("system") in INFRASTRUCTURE


def find_class(config: PluginConfig, environ: dict[str, str] | None = None) -> type[Plugin]:
    """The plugin class a config names (see the module text); a sensor's is its kind's."""
    kind = getattr(config, "kind", None)
    if kind is not None:  # a SensorConfig (launcher/sim/sensors)
        from launcher.sim.sensors import CLASSES

        module_name, _, attribute = CLASSES[kind].partition(":")
        return getattr(importlib.import_module(module_name), attribute)
    env = os.environ if environ is None else environ
    target = BUILTIN.get(canonical(config.filename)) or \
        CLASSIC.get(re.sub(r"^lib|\.so$", "", config.filename)) or \
        BUILTIN.get(canonical(config.name))
    if target is not None:
        module_name, _, attribute = target.partition(":")
        return getattr(importlib.import_module(module_name), attribute)
    stem = config.filename.removesuffix(".py")
    folders = [Path(p) for v in PLUGIN_VARIABLES for p in env.get(v, "").split(os.pathsep) if p]
    if config.filename.endswith(".so") or ".so." in config.filename or \
            _GZ_FILE.match(config.filename):
        raise PluginUnavailable(_unavailable(config, folders))
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
    where = ", ".join(str(f) for f in folders) or f"none of {', '.join(PLUGIN_VARIABLES)} is set"
    raise PluginError(f"{config.where}: unknown plugin '{config.filename}' (name "
                      f"'{config.name}'): not a built-in system and no {stem}.py in {where}"
                      f"{did_you_mean(config.filename, list(BUILTIN))}")


def _unavailable(config: PluginConfig, folders: list[Path]) -> str:
    label = f"plugin '{config.filename}' (name '{config.name}')"
    if _GZ_FILE.match(config.filename):
        return (f"{config.where}: {label} is a Gazebo system launcher does not provide; the "
                f"world runs without it (provided: {', '.join(sorted(_provided()))})")
    where = ", ".join(str(f) for f in folders) or \
        f"a folder of {' or '.join(PLUGIN_VARIABLES[:2])} (none is set)"
    return (f"{config.where}: {label} is a C++ library: launcher loads Python plugins only "
            f"(a .py file in {where}, or a Python module); the world runs without it")


def _provided() -> set[str]:
    from launcher.sim.sensors import SYSTEM_CLASSES

    return {name for name in BUILTIN if name.startswith("gz-sim-")} | set(SYSTEM_CLASSES)


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
