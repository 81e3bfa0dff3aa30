"""A URDF's XML and its link tree, checked: one root, no loops, joints naming real links.

Shared by the sim (which spawns URDF) and robot_state_publisher (which computes its
transforms); it imports neither MuJoCo nor numpy.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from launcher.errors import LaunchError


def line_of(text: str, element: ET.Element, tag: str) -> str:
    """Best-effort line of an element (ElementTree keeps none): the first matching name."""
    name = element.get("name")
    needle = f'<{tag} name="{name}"' if name else f"<{tag}"
    index = text.find(needle)
    return str(text.count("\n", 0, index) + 1) if index >= 0 else "?"


def place_of(text: str, element: ET.Element, tag: str) -> str:
    """`line:column` of an element, found as line_of finds it."""
    name = element.get("name")
    index = text.find(f'<{tag} name="{name}"' if name else f"<{tag}")
    if index < 0:
        return "?"
    return f"{text.count(chr(10), 0, index) + 1}:{index - text.rfind(chr(10), 0, index)}"


def parse_robot(text: str, label: str) -> ET.Element:
    """The <robot> element of a URDF; bad XML names its line and column."""
    try:
        robot = ET.fromstring(text)
    except ET.ParseError as exc:
        line, column = exc.position
        raise LaunchError(f"{label}:{line}:{column + 1}: invalid URDF: not valid XML "
                          f"({str(exc).split(':')[0]})") from None
    if robot.tag != "robot":
        raise LaunchError(f"{label}: invalid URDF: the top element is <{robot.tag}>, expected "
                          "<robot>")
    return robot


def root_link(robot: ET.Element, text: str, label: str) -> str:
    """The one root link of the tree the joints make; anything else is an error."""
    links = [link.get("name", "") for link in robot.findall("link")]
    if not links:
        raise LaunchError(f"{label}: invalid URDF: no <link>")
    parents: dict[str, str] = {}  # child link -> its joint
    for joint in robot.findall("joint"):
        where = f"{label}:{line_of(text, joint, 'joint')}"
        name = joint.get("name", "")
        parent, child = joint.find("parent"), joint.find("child")
        if parent is None or child is None:
            raise LaunchError(f"{where}: invalid URDF: joint '{name}' needs <parent link=…> "
                              "and <child link=…>")
        for end in (parent.get("link"), child.get("link")):
            if end not in links:
                raise LaunchError(f"{where}: invalid URDF: joint '{name}' names link '{end}', "
                                  "which is not defined")
        child_link = child.get("link", "")
        if child_link in parents:
            raise LaunchError(f"{where}: invalid URDF: link '{child_link}' has two parent "
                              f"joints ('{parents[child_link]}' and '{name}')")
        parents[child_link] = name
    roots = [link for link in links if link not in parents]
    if len(roots) != 1:
        reason = "no root link: the joints form a loop" if not roots else \
            f"{len(roots)} root links ({', '.join(roots)}); a URDF is one tree"
        raise LaunchError(f"{label}: invalid URDF: {reason}")
    return roots[0]
