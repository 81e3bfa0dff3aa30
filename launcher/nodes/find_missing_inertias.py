"""mujoco_ros2_control's `find_missing_inertias.py URDF`: the moving joints whose child link, and
the links fixed below it, have no mass and inertia (MuJoCo refuses such a body and its message
does not say which). Prints them, each at its line, and exits 1; else says all is well, 0."""

from __future__ import annotations

import argparse
import sys
import xml.etree.ElementTree as ET
from collections import defaultdict, deque
from pathlib import Path

from launcher.errors import reported
from launcher.sim.urdf_tree import line_of, parse_robot
from launcher.user_files import read_text

INERTIA = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}


def with_inertia(robot: ET.Element) -> set[str]:
    valid = set()
    for link in robot.findall("link"):
        inertial = link.find("inertial")
        mass = inertial.find("mass") if inertial is not None else None
        inertia = inertial.find("inertia") if inertial is not None else None
        if mass is not None and "value" in mass.attrib and inertia is not None and \
                INERTIA.issubset(inertia.attrib):
            valid.add(link.get("name", ""))
    return valid


def missing(robot: ET.Element) -> list[tuple[ET.Element, list[str]]]:
    """Each moving joint whose static subtree lacks mass and inertia, with that subtree."""
    valid = with_inertia(robot)
    below: dict[str, list[tuple[str, str]]] = defaultdict(list)
    joints = robot.findall("joint")
    for joint in joints:
        parent, child = joint.find("parent"), joint.find("child")
        if parent is not None and child is not None:
            below[parent.get("link", "")].append((child.get("link", ""),
                                                  joint.get("type", "fixed")))
    found = []
    for joint in joints:
        child = joint.find("child")
        if joint.get("type", "fixed") == "fixed" or child is None:
            continue
        start = child.get("link", "")
        seen, queue = [start], deque([start])
        while queue:
            link = queue.popleft()
            if link in valid:
                break
            for nxt, kind in below[link]:
                if kind == "fixed" and nxt not in seen:
                    seen.append(nxt)
                    queue.append(nxt)
        else:
            found.append((joint, seen))
    return found


def run(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(
        prog="find_missing_inertias.py",
        description="For each moving joint, report if its static-descendant subtree lacks "
                    "any valid mass+inertia link.")
    parser.add_argument("urdf_file", help="Path to your URDF file")
    path = parser.parse_args(argv).urdf_file
    text = read_text(Path(path))
    bad = missing(parse_robot(text, path))
    for joint, links in bad:
        print(f"Invalid joint: {joint.get('name', '<unnamed>')} "
              f"({path}:{line_of(text, joint, 'joint')})")
        print("  links:")
        print(f"    {', '.join(links)}")
    if bad:
        return 1
    print("All moving joints have at least one static descendant with valid mass & inertia.")
    return 0


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "find_missing_inertias")


if __name__ == "__main__":
    sys.exit(main())
