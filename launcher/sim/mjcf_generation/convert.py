"""URDF to MJCF as mujoco_ros2_control's `make_mjcf_from_robot_description` makes it, with
MuJoCo's own URDF compiler.

The steps are the converter's: the URDF gets MuJoCo's compiler settings (`balanceinertia`,
visuals kept, `fusestatic` unless `--no-fuse`), loses its `<collision>` elements (each visual
becomes a collision and a visual geom of the `collision` and `visual` classes), its meshes
are gathered into `assets/`; MuJoCo compiles it and writes it out as MJCF, to which the
scene and the raw inputs are added, every link as a site (frames.py), the processed inputs'
cameras at their links (turned half a turn about x: a MuJoCo camera looks down its -z, an
optical frame down its +z), lidar rangefinders replicated about theirs, and the
`modify_element` attributes. The result is checked by compiling it once more, so a mistake
in the inputs is said here, at its line, not by the sim that loads it.
"""

from __future__ import annotations

import copy
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco

from launcher.errors import LaunchError, did_you_mean
from launcher.sim.mjcf_generation.frames import LinkFrame, link_frames
from launcher.sim.mjcf_generation.inputs import Inputs
from launcher.sim.mjcf_generation.meshes import gather
from launcher.sim.transform import Pose, Quat, from_rpy
from launcher.sim.urdf_tree import parse_robot, root_link

URDF_OUT = "robot_description_formatted.urdf"
COMPILED = "mujoco_description.xml"
FORMATTED = "mujoco_description_formatted.xml"
FREE_JOINT = "floating_base_joint"
HALF_TURN_X = (0.0, 1.0, 0.0, 0.0)  # optical frame (+z forward) -> MuJoCo camera (-z)
RANGEFINDER_FRAME = (0.5, 0.5, 0.5, 0.5)  # a link's x (z up) -> the first rangefinder's z


class ConversionError(LaunchError):
    """A URDF, inputs or scene the converter cannot make an MJCF of."""


@dataclass
class Options:
    output: Path  # the folder for the URDF, the MJCF and assets/
    relative_assets: bool = False  # assetdir "assets" (files kept), else the absolute path
    fuse: bool = True  # MuJoCo's fusestatic
    add_free_joint: bool = False
    scene: list[ET.Element] = field(default_factory=list)  # merged into the MJCF
    pregenerated: Path | None = None  # -a: meshes made before


def convert(text: str, label: str, inputs: Inputs, options: Options,
            resolve: Callable[[str], Path], tools: Any) -> tuple[Path, list[str]]:
    """Write the MJCF of URDF `text` into `options.output`: its path, and warnings."""
    robot = parse_robot(text, label)
    root = root_link(robot, text, label)
    if options.add_free_joint and options.fuse and root != "world":
        robot, root = _with_floating_root(robot, root)
    frames = link_frames(robot, root)
    compiled, parts = _compile_urdf(copy.deepcopy(robot), label, options, resolve, tools,
                                    inputs.decompose)
    mjcf = ET.fromstring(compiled.read_text())
    if options.add_free_joint and root != "world":
        _free_joint(mjcf, root, options.fuse)
    _split_visuals(mjcf)
    _collide_as_parts(mjcf, parts)
    _drop_repeated_mimics(mjcf, inputs.raw)
    mjcf.extend(copy.deepcopy(options.scene))
    mjcf.extend(copy.deepcopy(inputs.raw))
    _add_sites(mjcf, frames, options.add_free_joint and root != "world")
    _add_cameras(mjcf, inputs)
    _add_lidars(mjcf, inputs)
    warnings = [f"decompose_mesh '{name}': the robot has no mesh of that name"
                f"{did_you_mean(name, _meshes(mjcf))}" for name in inputs.decompose
                if name not in parts]
    warnings += _modify(mjcf, inputs)
    out = options.output / FORMATTED
    ET.indent(mjcf)
    out.write_text(ET.tostring(mjcf, encoding="unicode") + "\n")
    try:
        mujoco.MjModel.from_xml_path(str(out))
    except ValueError as exc:
        message = " ".join(str(exc).split())
        hint = ""
        if re.search(r"unknown default class name '(visual|collision)'", message):
            hint = ("; each visual of the URDF becomes a geom of class 'visual' and one of "
                    "class 'collision': define both in <raw_inputs><default> (as "
                    "mujoco_ros2_control's test_inputs.xml does)")
        raise ConversionError(f"{out}: the MJCF made of {label} does not compile: "
                              f"{message}{hint}") from None
    return out, warnings


def _with_floating_root(robot: ET.Element, root: str) -> tuple[ET.Element, str]:
    """`-f` with fusing: a `virtual_base` link and a floating joint above the root link."""
    robot.insert(0, ET.Element("link", {"name": "virtual_base"}))
    joint = ET.Element("joint", {"name": "virtual_base_joint", "type": "floating"})
    ET.SubElement(joint, "parent", {"link": "virtual_base"})
    ET.SubElement(joint, "child", {"link": root})
    ET.SubElement(joint, "origin", {"xyz": "0 0 0", "rpy": "0 0 0"})
    robot.insert(1, joint)
    return robot, "virtual_base"


def _compile_urdf(robot: ET.Element, label: str, options: Options,
                  resolve: Callable[[str], Path], tools: Any,
                  decompose: dict[str, str]) -> tuple[Path, dict[str, list[str]]]:
    for parent in list(robot.iter()):
        for collision in parent.findall("collision"):
            parent.remove(collision)
    assets = options.output / "assets"
    parts = gather(robot, assets, resolve, options.pregenerated, tools, decompose)
    compiler = {"assetdir": "assets" if options.relative_assets else str(assets),
                "balanceinertia": "true", "discardvisual": "false", "strippath": "false"}
    if not options.fuse:
        compiler["fusestatic"] = "false"
    ET.SubElement(ET.SubElement(robot, "mujoco"), "compiler", compiler)
    urdf = options.output / URDF_OUT
    ET.indent(robot)
    urdf.write_text(ET.tostring(robot, encoding="unicode") + "\n")
    try:
        model = mujoco.MjModel.from_xml_path(str(urdf))
    except ValueError as exc:
        message = " ".join(str(exc).split())
        hint = ""
        if "mass and inertia" in message:
            hint = (f"; run `ros2 run mujoco_ros2_control find_missing_inertias.py {urdf}` to "
                    "see which moving links lack them")
        raise ConversionError(f"{label}: MuJoCo cannot compile the URDF: {message}{hint}") \
            from None
    compiled = options.output / COMPILED
    mujoco.mj_saveLastXML(str(compiled), model)
    return compiled, parts


def _free_joint(mjcf: ET.Element, root: str, fused: bool) -> None:
    """The floating joint MuJoCo made becomes a `<freejoint>` (no stiffness, no damping)."""
    if fused:
        for parent in mjcf.iter():
            for index, joint in enumerate(list(parent)):
                if joint.tag == "joint" and joint.get("name") == "virtual_base_joint" and \
                        joint.get("type") == "free":
                    parent.remove(joint)
                    parent.insert(index, ET.Element("freejoint", {"name": FREE_JOINT}))
                    return
    for body in mjcf.iter("body"):
        if body.get("name") == root:
            body.insert(0, ET.Element("freejoint", {"name": FREE_JOINT}))
            return
    raise ConversionError(f"-f: found neither virtual_base_joint nor the root link's body "
                          f"'{root}' to give a free joint")


def _split_visuals(mjcf: ET.Element) -> None:
    """Each geom MuJoCo made of a URDF visual becomes a `collision` and a `visual` geom."""
    worldbody = mjcf.find("worldbody")
    for parent in list(worldbody.iter()) if worldbody is not None else ():
        for geom in [g for g in parent.findall("geom") if "contype" in g.attrib]:
            collision = dict(geom.attrib)
            collision.setdefault("type", "sphere")
            for key in ("contype", "conaffinity", "group", "density"):
                collision.pop(key, None)
            visual = dict(collision, **{"class": "visual"})
            collision["class"] = "collision"
            collision.pop("rgba", None)
            parent.remove(geom)
            ET.SubElement(parent, "geom", collision)
            ET.SubElement(parent, "geom", visual)


def _collide_as_parts(mjcf: ET.Element, parts: dict[str, list[str]]) -> None:
    """A decomposed mesh collides as its convex parts: its collision geoms become one per
    part (meshes `<stem>_collision_<i>`, as obj2mjcf names them); its visuals stay whole."""
    asset = mjcf.find("asset")
    for stem, files in parts.items():
        whole = next((m for m in asset.iter("mesh") if m.get("name", _name(m)) == stem), None) \
            if asset is not None else None
        if whole is None:
            continue
        for file in files:
            mesh = ET.SubElement(asset, "mesh", {"name": Path(file).stem, "file": file})
            if whole.get("scale"):
                mesh.set("scale", whole.get("scale", ""))
        for parent in list(mjcf.iter()):
            for geom in [g for g in parent.findall("geom") if g.get("mesh") == stem and
                         g.get("class") == "collision"]:
                index = list(parent).index(geom)
                parent.remove(geom)
                for offset, file in enumerate(files):
                    parent.insert(index + offset, ET.Element(
                        "geom", dict(geom.attrib, mesh=Path(file).stem)))


def _name(mesh: ET.Element) -> str:
    """A mesh asset's name: its own, else its file's stem (MuJoCo's rule)."""
    return Path(mesh.get("file", "")).stem


def _meshes(mjcf: ET.Element) -> list[str]:
    return [m.get("name", _name(m)) for m in mjcf.iter("mesh")]


def _drop_repeated_mimics(mjcf: ET.Element, raw: list[ET.Element]) -> None:
    """MuJoCo makes a joint equality of a URDF `<mimic>`; where the raw inputs couple the
    same two joints (as inputs written for MuJoCo 3, which made none, do) it is dropped, so
    the pair is held once."""
    pairs = {_pair(joint) for equality in raw if equality.tag == "equality"
             for joint in equality.findall("joint")}
    for equality in mjcf.findall("equality"):
        for joint in equality.findall("joint"):
            if _pair(joint) in pairs:
                equality.remove(joint)
        if len(equality) == 0:
            mjcf.remove(equality)


def _pair(joint: ET.Element) -> frozenset[str]:
    return frozenset((joint.get("joint1", ""), joint.get("joint2", "")))


def _add_sites(mjcf: ET.Element, frames: dict[str, LinkFrame], floating: bool) -> None:
    bodies = {body.get("name"): body for body in mjcf.iter("body")}
    worldbody = mjcf.find("worldbody")
    for link, frame in frames.items():
        holder = worldbody if frame.at_root and not floating else bodies.get(frame.body)
        if holder is not None:
            ET.SubElement(holder, "site", {"name": link, "pos": _numbers(frame.pose.pos),
                                           "quat": _numbers(frame.pose.quat)})


def _sites(mjcf: ET.Element) -> dict[str, tuple[ET.Element, ET.Element]]:
    return {site.get("name", ""): (parent, site)
            for parent in mjcf.iter() for site in parent.findall("site")}


def _at_link(sites: dict[str, tuple[ET.Element, ET.Element]], link: str,
             what: str) -> tuple[ET.Element, ET.Element]:
    """The site a link became, and the element holding it; a link the robot lacks is an
    error naming `what` asked for it."""
    if link not in sites:
        raise ConversionError(f"{what}: '{link}' is not a link of the robot"
                              f"{did_you_mean(link, sites)}")
    return sites[link]


def _add_cameras(mjcf: ET.Element, inputs: Inputs) -> None:
    sites = _sites(mjcf)
    for link, camera in inputs.cameras.items():
        parent, site = _at_link(sites, link, f"camera '{camera.get('name', '')}' site")
        placed = copy.deepcopy(camera)
        placed.set("pos", site.get("pos", "0 0 0"))
        placed.set("quat", _numbers(_turned(_quat(site), HALF_TURN_X)))
        parent.append(placed)


def _add_lidars(mjcf: ET.Element, inputs: Inputs) -> None:
    sites = _sites(mjcf)
    for link, lidar in inputs.lidars.items():
        parent, site = _at_link(sites, link, "lidar ref_site")
        turn = from_rpy(0, 0, 0, 0, lidar.min_angle, 0).quat
        quat = _turned(_turned(_quat(site), RANGEFINDER_FRAME), turn)
        body = ET.SubElement(parent, "body", {"name": f"{link}_lidar_body",
                                              "pos": site.get("pos", "0 0 0"),
                                              "quat": _numbers(quat)})
        body.append(copy.deepcopy(lidar.replicate))


def _modify(mjcf: ET.Element, inputs: Inputs) -> list[str]:
    """Set the `modify_element` attributes; what no element matched (the converter passes
    over it in silence) is a warning."""
    worldbody = mjcf.find("worldbody")
    used = set()
    for element in worldbody.iter() if worldbody is not None else ():
        if element.tag == "geom":
            mesh = re.sub(r"_collision_\d+$", "", element.get("mesh", ""))
            key: tuple[str, object] = ("geom", (mesh, element.get("class", "")))
        else:
            key = (element.tag, element.get("name", ""))
        for name, value in inputs.modifiers.get(key, {}).items():
            element.set(name, value)
            used.add(key)
    return [f"modify_element: no {kind} {_described(what)} in the MJCF; nothing changed"
            for (kind, what) in inputs.modifiers if (kind, what) not in used]


def _described(what: object) -> str:
    if isinstance(what, tuple):
        return f"with mesh '{what[0]}' and class '{what[1]}'"
    return f"named '{what}'"


def _turned(quat: Quat, by: Quat) -> Quat:
    return (Pose(quat=quat) * Pose(quat=by)).quat


def _quat(site: ET.Element) -> Quat:
    w, x, y, z = (float(v) for v in site.get("quat", "1 0 0 0").split())
    return w, x, y, z


def _numbers(values: tuple[float, ...] | Pose) -> str:
    return " ".join("0" if abs(v) <= 1e-8 else f"{v:.12g}" for v in values)
