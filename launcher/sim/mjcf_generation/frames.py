"""Where each URDF link ends up in the MJCF MuJoCo makes of it.

MuJoCo's URDF import fuses a link fixed to its parent into that parent's body, so the link's
name is lost. mujoco_ros2_control's converter gives each link back as a site: in the body of
the nearest link above it whose joint moves (fixed joints and the links' own origins
chained), or in the world for the links fixed to the root.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import NamedTuple

from launcher.sim.transform import IDENTITY, Pose, from_rpy


class LinkFrame(NamedTuple):
    body: str  # the link whose body holds this link's site
    pose: Pose  # the site in that body
    at_root: bool  # fixed to the tree's root: the site goes into the world


def link_frames(robot: ET.Element, root: str) -> dict[str, LinkFrame]:
    joints = {joint.find("child").get("link"): joint  # type: ignore[union-attr]
              for joint in robot.findall("joint")}
    origins = {link.get("name", ""): _origin(link) for link in robot.findall("link")}
    frames: dict[str, LinkFrame] = {}
    for name in origins:
        link, pose = name, IDENTITY
        while True:
            if link == root:
                frames[name] = LinkFrame(link, pose, True)
                break
            joint = joints[link]
            if joint.get("type", "fixed") != "fixed":
                frames[name] = LinkFrame(link, pose, False)
                break
            pose = _origin(joint) * origins[link] * pose
            link = joint.find("parent").get("link", "")  # type: ignore[union-attr]
    return frames


def _origin(element: ET.Element) -> Pose:
    origin = element.find("origin")
    if origin is None:
        return IDENTITY
    xyz = [float(v) for v in origin.get("xyz", "0 0 0").split()]
    rpy = [float(v) for v in origin.get("rpy", "0 0 0").split()]
    return from_rpy(*xyz, *rpy)
