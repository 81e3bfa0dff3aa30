"""`<mujoco_inputs>`: what mujoco_ros2_control's converter adds to the MJCF it makes of a URDF.

Read from a file of their own (`<mujoco_inputs>` at the top) or from the URDF (`<robot>` with
a `<mujoco_inputs>` child), as `make_mjcf_from_robot_description -m` reads them:
`<raw_inputs>` (MJCF copied as written), `<processed_inputs>` (`camera` at a link, `lidar`
rangefinders replicated about a link, `modify_element`, `decompose_mesh`) and `<scene>`
(or a scene file whose top is `<mujoco>`). Each wrong input is an error at its line.
"""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from launcher.errors import did_you_mean
from launcher.sim.sdf.xmltree import Element, SdfError, parse

PROCESSED = ("camera", "lidar", "modify_element", "decompose_mesh")
DEFAULT_THRESHOLD = "0.05"  # decompose_mesh's, as the converter defaults it


class InputsError(SdfError):
    """A `<mujoco_inputs>` or scene file the converter cannot use."""


@dataclass
class Lidar:
    site: str  # the link the rangefinders turn about
    min_angle: float
    replicate: ET.Element  # MJCF <replicate> holding the rangefinders' site


@dataclass
class Inputs:
    raw: list[ET.Element] = field(default_factory=list)  # MJCF elements, copied as written
    cameras: dict[str, ET.Element] = field(default_factory=dict)  # link -> MJCF <camera>
    lidars: dict[str, Lidar] = field(default_factory=dict)  # link -> rangefinders
    modifiers: dict[tuple[str, object], dict[str, str]] = field(default_factory=dict)
    decompose: dict[str, str] = field(default_factory=dict)  # mesh name -> threshold


def read_inputs(text: str, label: str) -> Inputs:
    """The inputs in a `<mujoco_inputs>` file or in a URDF's `<mujoco_inputs>` (none: empty)."""
    block = _block(parse(text, label), label)
    inputs = Inputs()
    if block is None:
        return inputs
    raw = _one(block, "raw_inputs")
    if raw is not None:
        inputs.raw = [copy.deepcopy(child) for child in raw]
    processed = _one(block, "processed_inputs")
    for child in processed if processed is not None else ():
        _processed(child, inputs)
    return inputs


def read_scene(text: str, label: str) -> list[ET.Element]:
    """A scene's MJCF elements: a file whose top is `<mujoco>`, or a URDF's
    `<mujoco_inputs><scene>` (the last one, as the converter takes it)."""
    root = parse(text, label)
    if root.tag == "mujoco":
        return [copy.deepcopy(child) for child in root]
    block = _block(root, label)
    scenes = block.findall("scene") if block is not None else []
    return [copy.deepcopy(child) for child in scenes[-1]] if scenes else []


def _block(root: Element, label: str) -> Element | None:
    if root.tag == "mujoco_inputs":
        return root
    if root.tag != "robot":
        raise InputsError(f"{root.location()}: the top element is <{root.tag}>; expected "
                          "<mujoco_inputs> (an inputs file), <robot> (a URDF) or, for a "
                          "scene, <mujoco>")
    return root.find("mujoco_inputs")  # type: ignore[return-value]


def _one(block: Element, tag: str) -> Element | None:
    found = block.findall(tag)
    if len(found) > 1:
        raise found[1].error(f"a second <{tag}> in <mujoco_inputs>; one is allowed")
    return found[0] if found else None  # type: ignore[return-value]


def _processed(child: Element, inputs: Inputs) -> None:
    if child.tag == "camera":
        site = _needed(child, "site")
        camera = ET.Element("camera", {k: v for k, v in child.attrib.items() if k != "site"})
        inputs.cameras[site] = camera
    elif child.tag == "lidar":
        _lidar(child, inputs)
    elif child.tag == "modify_element":
        _modifier(child, inputs)
    elif child.tag == "decompose_mesh":
        inputs.decompose[_needed(child, "mesh_name")] = child.get("threshold",
                                                                  DEFAULT_THRESHOLD)
    else:
        nearest = did_you_mean(child.tag, PROCESSED)
        raise child.error(f"<{child.tag}> is not a processed input{nearest} (processed "
                          f"inputs: {', '.join(PROCESSED)})")


def _lidar(child: Element, inputs: Inputs) -> None:
    site, name = _needed(child, "ref_site"), _needed(child, "sensor_name")
    low, high, step = (_number(child, key) for key in ("min_angle", "max_angle",
                                                         "angle_increment"))
    if step <= 0:
        raise child.error(f"angle_increment is {step:g}; it must be greater than zero")
    count = int((high - low) / step) + 1  # the converter's count, rounding as it does
    replicate = ET.Element("replicate", {"site": site, "count": str(count), "sep": "-",
                                         "offset": "0 0 0", "euler": f"0 {step} 0"})
    ET.SubElement(replicate, "site", {"name": name, "pos": "0.0 0.0 0.0",
                                      "quat": "0.0 0.0 0.0 1.0"})
    inputs.lidars[site] = Lidar(site, low, replicate)


def _modifier(child: Element, inputs: Inputs) -> None:
    attributes = dict(child.attrib)
    kind = attributes.pop("type", None)
    if kind is None:
        raise child.error("<modify_element> needs type= (the MJCF element to change: joint, "
                          "body, geom, …)")
    key: tuple[str, object]
    if kind == "geom":
        mesh, geom_class = attributes.pop("mesh", None), attributes.pop("class", None)
        if mesh is None or geom_class is None:
            raise child.error("<modify_element type=\"geom\"> needs mesh= and class= (a geom "
                              "is found by its mesh and class)")
        key = (kind, (mesh, geom_class))
    else:
        name = attributes.pop("name", None)
        if name is None:
            raise child.error(f"<modify_element type=\"{kind}\"> needs name= (the {kind} to "
                              "change)")
        key = (kind, name)
    inputs.modifiers[key] = attributes


def _needed(child: Element, key: str) -> str:
    value = child.get(key)
    if not value:
        raise child.error(f"<{child.tag}> needs {key}=")
    return value


def _number(child: Element, key: str) -> float:
    value = _needed(child, key)
    try:
        return float(value)
    except ValueError:
        raise child.error(f"{key}=\"{value}\" is not a number") from None
