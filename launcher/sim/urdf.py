"""Preparing URDF for MuJoCo: checks, plugin tags, mesh URIs, and the compiler flags it needs.

MuJoCo's URDF import fuses fixed links into the world and drops visuals unless told not to,
and knows nothing of `package://` or Gazebo's tags. Here the URDF's tree is checked
(urdf_tree.py), `<gazebo><plugin>` and `<mujoco><plugin>` elements are taken
out as plugin configs, `<gazebo reference="link"><mu1>` becomes that link's friction, mesh
URIs become absolute paths, and `<mujoco><compiler fusestatic="false" discardvisual="false"/>`
is set.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from launcher.errors import LaunchError
from launcher.sim.mjcf import PluginConfig
from launcher.sim.resources import resolve_uri
from launcher.sim.urdf_tree import line_of, parse_robot, root_link


@dataclass
class Urdf:
    text: str
    name: str
    root_link: str
    plugins: list[PluginConfig] = field(default_factory=list)
    friction: dict[str, float] = field(default_factory=dict)  # link -> sliding friction


def prepare(text: str, label: str, base: Path | None, packages: object | None = None,
            environ: Mapping[str, str] | None = None) -> Urdf:
    robot = parse_robot(text, label)
    root = root_link(robot, text, label)
    result = Urdf("", robot.get("name", "robot"), root)
    for gazebo in robot.findall("gazebo"):
        for plugin in gazebo.findall("plugin"):
            result.plugins.append(PluginConfig(plugin.get("filename", ""),
                                               plugin.get("name", ""), plugin,
                                               f"{label}:{line_of(text, plugin, 'plugin')}"))
        reference = gazebo.get("reference")
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
