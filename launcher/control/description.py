"""The `<ros2_control>` blocks of a URDF, read as ros2_control's component parser reads them.

    <ros2_control name="GazeboSimSystem" type="system">
      <hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin><param name="…">…</param>
      </hardware>
      <joint name="slider_to_cart">
        <command_interface name="position"><param name="min">-15</param>…</command_interface>
        <state_interface name="position"><param name="initial_value">5.0</param></state_interface>
      </joint>
      <sensor name="imu"><state_interface name="orientation.x"/>…</sensor>
    </ros2_control>

Interfaces are named `<joint or sensor>/<interface>` (`slider_to_cart/position`). A joint of
the block whose URDF joint has `<mimic>` follows the joint it mimics (unless the block says
`mimic="false"`). Mistakes name the URDF's file:line.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from launcher.errors import LaunchError, did_you_mean

# the hardware plugins launcher provides: the sim's joints, or commands mirrored to states
SIM_PLUGINS = ("gz_ros2_control/GazeboSimSystem", "ign_ros2_control/IgnitionSystem",
               "gazebo_ros2_control/GazeboSystem")
MOCK_PLUGINS = ("mock_components/GenericSystem", "fake_components/GenericSystem")
# mujoco_ros2_control's: the MJCF's own actuators (started by its ros2_control_node)
MUJOCO_PLUGINS = ("mujoco_ros2_control/MujocoSystemInterface",
                  "mujoco_ros2_control/MujocoSystem")
PLUGINS = SIM_PLUGINS + MOCK_PLUGINS + MUJOCO_PLUGINS
TRANSMISSIONS = ("transmission_interface/SimpleTransmission",
                 "transmission_interface/DifferentialTransmission")
TYPES = ("system", "actuator", "sensor")


@dataclass
class Interface:
    name: str
    min: float = -math.inf
    max: float = math.inf
    initial_value: float | None = None
    params: dict[str, str] = field(default_factory=dict)


@dataclass
class Component:
    """A joint or a sensor of a hardware block, with its interfaces."""

    name: str
    kind: str  # "joint", "sensor" or "gpio"
    command_interfaces: list[Interface] = field(default_factory=list)
    state_interfaces: list[Interface] = field(default_factory=list)
    params: dict[str, str] = field(default_factory=dict)
    mimic: tuple[str, float, float] | None = None  # (joint, multiplier, offset)


@dataclass
class Transmission:
    """A `<transmission>` of the block: its joints' and actuators' names, roles, mechanical
    reductions and offsets (transmission_interface's)."""

    name: str
    plugin: str
    joints: list[tuple[str, str, float, float]] = field(default_factory=list)  # name, role, …
    actuators: list[tuple[str, str, float]] = field(default_factory=list)  # name, role, reduction


@dataclass
class Hardware:
    name: str
    type: str
    plugin: str
    where: str  # file:line of the block
    params: dict[str, str] = field(default_factory=dict)
    joints: list[Component] = field(default_factory=list)
    sensors: list[Component] = field(default_factory=list)
    gpios: list[Component] = field(default_factory=list)
    transmissions: list[Transmission] = field(default_factory=list)

    @property
    def components(self) -> list[Component]:
        return [*self.joints, *self.sensors, *self.gpios]

    @property
    def is_sim(self) -> bool:
        return self.plugin in SIM_PLUGINS

    @property
    def is_mujoco(self) -> bool:
        return self.plugin in MUJOCO_PLUGINS

    def command_names(self) -> list[str]:
        return [f"{c.name}/{i.name}" for c in self.components for i in c.command_interfaces]

    def state_names(self) -> list[str]:
        return [f"{c.name}/{i.name}" for c in self.components for i in c.state_interfaces]


def parse(text: str, label: str) -> list[Hardware]:
    """Every `<ros2_control>` block of the URDF `text` (read from `label`)."""
    try:
        robot = ET.fromstring(text)
    except ET.ParseError as exc:
        line, column = exc.position
        raise LaunchError(f"{label}:{line}:{column + 1}: invalid URDF: not valid XML") from None
    joints = {j.get("name", ""): j for j in robot.iter("joint") if j.find("parent") is not None}
    blocks = robot.findall("ros2_control")
    return [_hardware(block, joints, text, label, index) for index, block in enumerate(blocks)]


def _hardware(block: ET.Element, joints: dict[str, ET.Element], text: str, label: str,
              index: int) -> Hardware:
    where = f"{label}:{_line(text, 'ros2_control', index)}"
    name = block.get("name", "")
    kind = block.get("type", "system").lower()
    if kind not in TYPES:
        raise LaunchError(f"{where}: <ros2_control name=\"{name}\"> has type '{kind}'; expected "
                          f"{', '.join(TYPES)}{did_you_mean(kind, TYPES)}")
    hardware = block.find("hardware")
    plugin = (hardware.findtext("plugin") if hardware is not None else "") or ""
    plugin = plugin.strip()
    if not plugin:
        raise LaunchError(f"{where}: <ros2_control name=\"{name}\"> has no "
                          f"<hardware><plugin>; expected one of {', '.join(PLUGINS)}")
    if plugin not in PLUGINS:
        raise LaunchError(f"{where}: <ros2_control name=\"{name}\">: unknown hardware plugin "
                          f"'{plugin}'; launcher provides {', '.join(PLUGINS)}"
                          f"{did_you_mean(plugin, PLUGINS)}")
    result = Hardware(name, kind, plugin, where, _params(hardware))
    for element in block:
        if element.tag == "joint":
            component = _component(element, "joint", where)
            if component.name not in joints:
                raise LaunchError(f"{where}: <ros2_control name=\"{name}\">: joint "
                                  f"'{component.name}' is not a joint of the URDF"
                                  f"{did_you_mean(component.name, joints)}")
            mimic = joints[component.name].find("mimic")
            if mimic is not None and element.get("mimic", "true").lower() != "false":
                component.mimic = (mimic.get("joint", ""),
                                   _number(mimic.get("multiplier", "1"), where),
                                   _number(mimic.get("offset", "0"), where))
            result.joints.append(component)
        elif element.tag == "sensor":
            result.sensors.append(_component(element, "sensor", where))
        elif element.tag == "gpio":
            result.gpios.append(_component(element, "gpio", where))
        elif element.tag == "transmission":
            result.transmissions.append(_transmission(element, where))
    return result


def _transmission(element: ET.Element, where: str) -> Transmission:
    name = element.get("name", "")
    plugin = (element.findtext("plugin") or "").strip()
    if plugin not in TRANSMISSIONS:
        raise LaunchError(f"{where}: <transmission name=\"{name}\">: unknown plugin "
                          f"'{plugin}'; expected {' or '.join(TRANSMISSIONS)}"
                          f"{did_you_mean(plugin, TRANSMISSIONS)}")
    result = Transmission(name, plugin)
    for joint in element.findall("joint"):
        result.joints.append((joint.get("name", ""), joint.get("role", ""),
                              _number(joint.findtext("mechanical_reduction") or "1", where),
                              _number(joint.findtext("offset") or "0", where)))
    for actuator in element.findall("actuator"):
        result.actuators.append((actuator.get("name", ""), actuator.get("role", ""),
                                 _number(actuator.findtext("mechanical_reduction") or "1",
                                         where)))
    wanted = 1 if plugin.endswith("SimpleTransmission") else 2
    if len(result.joints) != wanted or len(result.actuators) != wanted:
        raise LaunchError(f"{where}: <transmission name=\"{name}\"> ({plugin}) needs "
                          f"{wanted} joint(s) and {wanted} actuator(s); it has "
                          f"{len(result.joints)} and {len(result.actuators)}")
    return result


def _component(element: ET.Element, kind: str, where: str) -> Component:
    component = Component(element.get("name", ""), kind, params=_params(element))
    for tag, into in (("command_interface", component.command_interfaces),
                      ("state_interface", component.state_interfaces)):
        for item in element.findall(tag):
            params = _params(item)
            interface = Interface(item.get("name", ""), params=params)
            if "min" in params:
                interface.min = _number(params["min"], where)
            if "max" in params:
                interface.max = _number(params["max"], where)
            if "initial_value" in params:
                interface.initial_value = _number(params["initial_value"], where)
            into.append(interface)
    return component


def _params(element: ET.Element | None) -> dict[str, str]:
    if element is None:
        return {}
    return {p.get("name", ""): (p.text or "").strip() for p in element.findall("param")}


def _number(text: str, where: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise LaunchError(f"{where}: '{text}' is not a number") from None


def _line(text: str, tag: str, index: int) -> int:
    """The line of the `index`th `<tag` in `text` (ElementTree keeps no lines)."""
    at = -1
    for _ in range(index + 1):
        at = text.find(f"<{tag}", at + 1)
        if at < 0:
            return 0
    return text.count("\n", 0, at) + 1
