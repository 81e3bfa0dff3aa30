"""Preparing URDF for MuJoCo: checks, plugin tags, mesh URIs, and the compiler flags it needs.

MuJoCo's URDF import fuses fixed links into the world and drops visuals unless told not to,
and knows nothing of `package://` or Gazebo's tags. Here the URDF's tree is checked
(urdf_tree.py), `<gazebo><plugin>` and `<mujoco><plugin>` elements are taken
out as plugin configs, `<gazebo reference="link"><sensor>` as that link's sensors (most ROS
robots declare theirs so), `<gazebo reference="link"><mu1>` becomes that link's friction, mesh
URIs become absolute paths, and `<mujoco><compiler fusestatic="false" discardvisual="false"/>`
is set.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, did_you_mean
from launcher.sim.mjcf import PluginConfig
from launcher.sim.resources import resolve_uri
from launcher.sim.sdf.pose import Pose, parse_pose
from launcher.sim.sdf.xmltree import parse
from launcher.sim.sensors.config import SensorConfig, sensor_config
from launcher.sim.urdf_tree import line_of, parse_robot, place_of, root_link


@dataclass
class Urdf:
    text: str
    name: str
    root_link: str
    plugins: list[PluginConfig] = field(default_factory=list)
    friction: dict[str, float] = field(default_factory=dict)  # link -> sliding friction
    sensors: list[tuple[SensorConfig, Pose]] = field(default_factory=list)  # and their poses
    warnings: list[str] = field(default_factory=list)


def prepare(text: str, label: str, base: Path | None, packages: object | None = None,
            environ: Mapping[str, str] | None = None) -> Urdf:
    robot = parse_robot(text, label)
    root = root_link(robot, text, label)
    result = Urdf("", robot.get("name", "robot"), root)
    preserved = _preserved_joints(robot)
    for gazebo in robot.findall("gazebo"):
        for plugin in gazebo.findall("plugin"):
            result.plugins.append(PluginConfig(plugin.get("filename", ""),
                                               plugin.get("name", ""), plugin,
                                               f"{label}:{line_of(text, plugin, 'plugin')}",
                                               robot=text))
        reference = gazebo.get("reference")
        for sensor in gazebo.findall("sensor"):
            _sensor(result, robot, text, label, sensor, reference, preserved)
        mu = gazebo.find("mu1")
        if reference and mu is not None and (mu.text or "").strip():
            result.friction[reference] = float(mu.text)
        robot.remove(gazebo)
    mujoco_tag = robot.find("mujoco")
    if mujoco_tag is None:
        mujoco_tag = ET.SubElement(robot, "mujoco")
    for plugin in mujoco_tag.findall("plugin"):
        result.plugins.append(PluginConfig(plugin.get("filename", plugin.get("name", "")),
                                           plugin.get("name", ""), plugin, label))
        mujoco_tag.remove(plugin)
    compiler = mujoco_tag.find("compiler")
    if compiler is None:
        compiler = ET.SubElement(mujoco_tag, "compiler")
    compiler.set("fusestatic", "false")
    compiler.set("discardvisual", "false")
    compiler.set("strippath", "false")
    for mesh in robot.iter("mesh"):
        uri = mesh.get("filename")
        if uri:
            try:
                mesh.set("filename", str(resolve_uri(uri, base, packages, environ)))
            except LaunchError as exc:
                raise LaunchError(f"{label}: mesh {exc}") from None
    result.text = ET.tostring(robot, encoding="unicode")
    return result


def _sensor(result: Urdf, robot: ET.Element, text: str, label: str, sensor: ET.Element,
            reference: str | None, preserved: set[str]) -> None:
    """A `<gazebo reference="link"><sensor>`: read as SDF reads it (at its own place in the
    URDF), on the link it names, or on a joint (at the joint, on its child link); a reference
    to neither is a warning, the sensor left out."""
    place = place_of(text, sensor, "sensor")
    line, column = (int(n) for n in place.split(":")) if place != "?" else (1, 1)
    # the sensor's XML at its own place, so what SDF's reader says of it points into the URDF
    element = parse("\n" * (line - 1) + " " * (column - 1)
                    + ET.tostring(sensor, encoding="unicode"), label)

    def warn(where: Any, message: str) -> None:
        result.warnings.append(f"{where.location.file}:{where.location.line}: {message}")

    links = [link.get("name", "") for link in robot.findall("link")]
    joints = {joint.get("name", ""): joint.find("child").get("link", "")
              for joint in robot.findall("joint") if joint.find("child") is not None}
    if reference in joints:  # a joint's sensor (force_torque), on its child at the joint
        config = sensor_config(element, joints[reference], warn, joint=reference)
        if config is not None:
            result.sensors.append((config, parse_pose(element.find("pose"))))
        return
    if reference not in links:
        result.warnings.append(
            f"{label}:{place}: sensor '{sensor.get('name', '')}': <gazebo reference="
            f"\"{reference or ''}\"> names no link or joint of the robot"
            f"{did_you_mean(reference or '', [*links, *joints])}; it is left out")
        return

    config = sensor_config(element, reference, warn)
    if config is not None:
        config.named_link = _lumped_into(robot, reference, preserved)
        result.sensors.append((config, parse_pose(element.find("pose"))))


def _preserved_joints(robot: ET.Element) -> set[str]:
    """The fixed joints whose `<gazebo reference>` says `<preserveFixedJoint>` or
    `<disableFixedJointLumping>`: Gazebo keeps their child links as links of their own."""
    return {gazebo.get("reference", "") for gazebo in robot.findall("gazebo")
            for tag in ("preserveFixedJoint", "disableFixedJointLumping")
            if (gazebo.findtext(tag) or "").strip().lower() in ("true", "1")}


def _lumped_into(robot: ET.Element, link: str, kept: set[str]) -> str:
    """The link Gazebo's URDF import merges `link` into: up through fixed joints, except
    preserved ones."""
    parent_of = {(joint.find("child").get("link") if joint.find("child") is not None else None):
                 joint for joint in robot.findall("joint")}
    seen = {link}
    while (joint := parent_of.get(link)) is not None and joint.get("type") == "fixed" \
            and joint.get("name") not in kept and joint.find("parent") is not None:
        link = joint.find("parent").get("link", link)
        if link in seen:
            break
        seen.add(link)
    return link
