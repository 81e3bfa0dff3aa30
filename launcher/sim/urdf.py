"""Preparing URDF for MuJoCo: checks, plugin tags, mesh URIs, and the compiler flags it needs.

MuJoCo's URDF import fuses fixed links into the world and drops visuals unless told not to,
and knows nothing of `package://` or Gazebo's tags. Here the URDF is checked (one root, no
loops, joints naming real links), `<gazebo><plugin>` and `<mujoco><plugin>` elements are taken
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


@dataclass
class Urdf:
    text: str
    name: str
    root_link: str
    plugins: list[PluginConfig] = field(default_factory=list)
    friction: dict[str, float] = field(default_factory=dict)  # link -> sliding friction


def _line_of(text: str, element: ET.Element, tag: str) -> str:
    """Best-effort line of an element (ElementTree keeps none): the first matching name."""
    name = element.get("name")
    needle = f'<{tag} name="{name}"' if name else f"<{tag}"
    index = text.find(needle)
    return str(text.count("\n", 0, index) + 1) if index >= 0 else "?"


def prepare(text: str, label: str, base: Path | None, packages: object | None = None,
            environ: Mapping[str, str] | None = None) -> Urdf:
    try:
        robot = ET.fromstring(text)
    except ET.ParseError as exc:
        line, column = exc.position
        raise LaunchError(f"{label}:{line}:{column + 1}: invalid URDF: not valid XML "
                          f"({str(exc).split(':')[0]})") from None
    if robot.tag != "robot":
        raise LaunchError(f"{label}: invalid URDF: the top element is <{robot.tag}>, expected "
                          "<robot>")
    links = [link.get("name", "") for link in robot.findall("link")]
    if not links:
        raise LaunchError(f"{label}: invalid URDF: no <link>")
    parents: dict[str, str] = {}
    for joint in robot.findall("joint"):
        where = f"{label}:{_line_of(text, joint, 'joint')}"
        parent = joint.find("parent")
        child = joint.find("child")
        if parent is None or child is None:
            raise LaunchError(f"{where}: invalid URDF: joint '{joint.get('name')}' needs "
                              "<parent link=…> and <child link=…>")
        for end in (parent.get("link"), child.get("link")):
            if end not in links:
                raise LaunchError(f"{where}: invalid URDF: joint '{joint.get('name')}' names "
                                  f"link '{end}', which is not defined")
        if child.get("link") in parents:
            raise LaunchError(f"{where}: invalid URDF: link '{child.get('link')}' has two "
                              "parent joints")
        parents[child.get("link", "")] = parent.get("link", "")
    roots = [link for link in links if link not in parents]
    if len(roots) != 1:
        reason = "no root link (the joints form a loop)" if not roots else \
            f"{len(roots)} root links ({', '.join(roots)}); expected one tree"
        raise LaunchError(f"{label}: invalid URDF: {reason}")
    result = Urdf("", robot.get("name", "robot"), roots[0])
    for gazebo in robot.findall("gazebo"):
        for plugin in gazebo.findall("plugin"):
            result.plugins.append(PluginConfig(plugin.get("filename", ""),
                                               plugin.get("name", ""), plugin,
                                               f"{label}:{_line_of(text, plugin, 'plugin')}"))
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
