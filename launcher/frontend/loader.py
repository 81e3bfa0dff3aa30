"""Load a launch file of any format into a LaunchDescription, by its extension."""

from __future__ import annotations

import os
from pathlib import Path

from launcher.description.action import LaunchDescription
from launcher.errors import LaunchError, Location, ParseError
from launcher.frontend import parse_cache
from launcher.frontend.builder import build_description
from launcher.frontend.entity import Entity
from launcher.user_files import check_readable, read_bytes

# Each format's loader is imported when a file of that format is parsed (PyYAML alone is a
# fifth of `launcher launch`'s imports), and parse_cache keeps what it parsed for the next run.

FORMATS = (".yaml", ".yml", ".xml", ".launch", ".test", ".py")  # .launch, .test: roslaunch's
# (or ROS 2's) XML; .test: rostest's, whose <test>s roslaunch leaves out
# Parsed YAML/XML descriptions, by path and modification time: including a file N times (one
# spawn file per robot) parses it once. Descriptions are not changed by running them.
_cache: dict[Path, tuple[int, LaunchDescription]] = {}


def launch_format(path: Path) -> str:
    for suffix in FORMATS:
        if path.name.endswith(suffix):
            return suffix
    raise ParseError(
        f"cannot tell the launch file's format from its name; expected a name ending in "
        f"{', '.join(FORMATS)}", Location(str(path)))


def load_file(path: Path) -> LaunchDescription:
    path = Path(os.path.abspath(path))
    kind = launch_format(path)
    try:
        if kind == ".py":
            check_readable(path)
        else:
            stamp = path.stat().st_mtime_ns
            cached = _cache.get(path)
            if cached and cached[0] == stamp:
                return cached[1]
            data = read_bytes(path)
    except LaunchError as exc:
        raise ParseError(f"cannot be a launch file: {exc.message}",
                         Location(str(path))) from None
    except FileNotFoundError:
        raise ParseError("no such launch file", Location(str(path))) from None
    except IsADirectoryError:
        raise ParseError("this is a folder, not a launch file", Location(str(path))) from None
    except OSError as exc:
        raise ParseError(f"cannot read: {exc.strerror}", Location(str(path))) from None
    if kind == ".py":
        from launcher.frontend.python_loader import load_python

        return load_python(path)
    try:
        root = parse_cache.get(path, data)
        if root is None:
            root = _parse(kind, data, path)
            parse_cache.put(path, data, root)
        description = build_description(root, path)
    except RecursionError:  # nested past what the loaders check for (`- - - - …` on one line)
        raise ParseError("nested too deeply to read", Location(str(path))) from None
    _cache[path] = (stamp, description)
    return description


def _parse(kind: str, data: bytes, path: Path) -> Entity:
    if kind in (".xml", ".launch", ".test"):
        from launcher.frontend import ros1
        from launcher.frontend.xml_loader import load_xml

        root = load_xml(data, str(path))
        default = "ros1" if kind in (".launch", ".test") else "ros2"
        if ros1.dialect(root, default) == "ros1":
            return ros1.translate(root)
        if "deprecated" in root.attributes:  # roslaunch's alone
            raise ParseError("<launch> takes no attribute 'deprecated' (roslaunch's, not ROS "
                             "2's)", root.location)
        return root
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ParseError(f"not UTF-8 text: {exc.reason} at byte {exc.start}",
                         Location(str(path))) from None
    from launcher.frontend.yaml_loader import load_yaml

    return load_yaml(text, str(path))
