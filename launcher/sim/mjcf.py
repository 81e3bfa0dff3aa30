"""Reading MJCF: jinja2 templates, launcher plugin elements, URIs, and MuJoCo's errors.

A file ending `.j2` is rendered first (undefined variables are errors). Direct children
`<plugin filename="…" name="…">…</plugin>` of `<mujoco>` are launcher plugins (Gazebo's shape),
which MuJoCo would reject: they are taken out and blanked with the same number of lines, so
MuJoCo's line numbers still point into the file. So is mujoco_ros2_control's lidar extension
(`<extension><plugin plugin="mujoco.plugin.lidar">` and the `<sensor><plugin>`s using it, a C++
plugin MuJoCo's Python does not have): each such sensor becomes a world plugin config of that
name, its `<config>`s (the instance's, then its own) gathered into one element
(sim/plugins/mjcf_lidar.py casts its rays). `file="model://…"`/`package://` attributes
are rewritten to absolute paths. `<include file="…">` is found relative to the including file
(then the top file's folder, as MuJoCo looks) or through a URI, and handed to MuJoCo with the
text, so a model read from a string includes as one read from its file.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from xml.parsers import expat

import mujoco

from launcher.errors import LaunchError
from launcher.sim.resources import resolve_uri
from launcher.user_files import read_text

_URI = re.compile(r'(\bfile\s*=\s*")((?:model|package|file)://[^"]*)(")')
_INCLUDE = re.compile(r'<include\s[^>]*?\bfile\s*=\s*"([^"]*)"')
MAX_INCLUDES = 1000  # files one model may include, all levels together (a loop ends here)


@dataclass
class PluginConfig:
    filename: str
    name: str
    element: ET.Element
    where: str  # file:line, for messages
    robot: str = ""  # a URDF plugin's robot description (gz_ros2_control reads its blocks)
    namespace: str = ""  # its entity's (entity_namespace): a ROS plugin's names go under it


@dataclass
class Source:
    text: str
    path: Path | None
    plugins: list[PluginConfig] = field(default_factory=list)
    includes: dict[str, bytes] = field(default_factory=dict)  # as written in file="…"

    @property
    def label(self) -> str:
        return str(self.path) if self.path else "<string>"


def render_template(text: str, path: Path, values: Mapping[str, str]) -> str:
    import jinja2

    environment = jinja2.Environment(undefined=jinja2.StrictUndefined, keep_trailing_newline=True,
                                     loader=jinja2.FileSystemLoader(str(path.parent)))
    try:
        return environment.from_string(text).render(**values)
    except jinja2.UndefinedError as exc:
        given = ", ".join(sorted(values)) or "none"
        raise LaunchError(f"{path}: template error: {exc.message}; pass it with --world-arg "
                          f"NAME=VALUE (given: {given})") from None
    except jinja2.TemplateSyntaxError as exc:
        raise LaunchError(f"{path}:{exc.lineno}: template syntax error: {exc.message}") from None


def read(text: str, path: Path | None, values: Mapping[str, str] | None = None,
         environ: Mapping[str, str] | None = None, rendered: bool = False) -> Source:
    if path is not None and path.name.endswith(".j2") and not rendered:
        text = render_template(text, path, values or {})
    source = Source(text, path)
    _take_plugins(source)
    _take_lidars(source)
    base = path.parent if path else None
    source.text = _uris(source.text, base, environ)
    if base is not None:
        _gather_includes(source, source.text, base, base, environ)
    return source


def _uris(text: str, base: Path | None, environ: Mapping[str, str] | None) -> str:
    return _URI.sub(lambda m: m.group(1) + str(resolve_uri(m.group(2), base, environ=environ))
                    + m.group(3), text)


def _gather_includes(source: Source, text: str, folder: Path, top: Path,
                     environ: Mapping[str, str] | None, label: str | None = None) -> None:
    """Every file `text` (the file `label`) includes, and those they include, into
    `source.includes`; a missing one is said at its tag's line and column."""
    for match in _INCLUDE.finditer(text):
        written = match.group(1)
        if written in source.includes:
            continue
        if len(source.includes) >= MAX_INCLUDES:
            raise LaunchError(f"{source.label}: more than {MAX_INCLUDES} included files "
                              f"(does a file include itself?)")
        found = next((p for p in (folder / written, top / written) if p.is_file()), None)
        if found is None:
            looked = " and ".join(dict.fromkeys(str(p) for p in (folder / written,
                                                                 top / written)))
            line = text.count("\n", 0, match.start()) + 1
            column = match.start() - text.rfind("\n", 0, match.start())
            raise LaunchError(f"{label or source.label}:{line}:{column}: <include "
                              f"file=\"{written}\">: no such file (looked for {looked})")
        included = _uris(read_text(found), found.parent, environ)
        source.includes[written] = included.encode()
        _gather_includes(source, included, found.parent, top, environ, str(found))


LIDAR_PLUGIN = "mujoco.plugin.lidar"


def _take_lidars(source: Source) -> None:
    """Take out the lidar extension and the sensors that use it; each sensor a plugin
    config (`filename` mujoco.plugin.lidar, `name` the sensor's)."""
    if LIDAR_PLUGIN not in source.text:
        return
    data = source.text.encode()
    found: list[tuple[str, int, int, int, ET.Element]] = []  # parent, start, stop, line
    parser = expat.ParserCreate()
    stack: list[str] = []
    starts: list[tuple[int, int]] = []

    def start(tag: str, _attrs: dict[str, str]) -> None:
        stack.append(tag)
        if len(stack) == 3 and tag == "plugin" and stack[1] in ("extension", "sensor"):
            starts.append((parser.CurrentByteIndex, parser.CurrentLineNumber))

    def end(tag: str) -> None:
        if len(stack) == 3 and tag == "plugin" and stack[1] in ("extension", "sensor"):
            begin, line = starts.pop()
            stop = parser.CurrentByteIndex
            if data.startswith(b"</", stop):
                stop = data.index(b">", stop) + 1
            found.append((stack[1], begin, stop, line,
                          ET.fromstring(data[begin:stop].decode())))
        stack.pop()

    parser.StartElementHandler, parser.EndElementHandler = start, end
    parser.Parse(data, True)  # (read once already by _take_plugins: valid XML)
    instances: dict[str, dict[str, str]] = {}
    for parent, _, _, _, element in found:
        if parent == "extension" and element.get("plugin") == LIDAR_PLUGIN:
            for instance in element.findall("instance"):
                instances[instance.get("name", "")] = _configs(instance)
    taken = []
    for parent, begin, stop, line, element in found:
        if parent == "extension":
            if element.get("plugin") == LIDAR_PLUGIN:
                taken.append((begin, stop))
            continue
        instance = element.get("instance")
        if element.get("plugin") != LIDAR_PLUGIN and instance not in instances:
            continue
        config = ET.Element("lidar", {k: v for k, v in element.attrib.items()
                                      if k not in ("plugin", "instance")})
        for key, value in {**instances.get(instance or "", {}), **_configs(element)}.items():
            ET.SubElement(config, "config", {"key": key, "value": value})
        name = element.get("name", "")
        source.plugins.append(PluginConfig(LIDAR_PLUGIN, name, config,
                                           f"{source.label}:{line}"))
        taken.append((begin, stop))
    for begin, stop in sorted(taken, reverse=True):
        data = data[:begin] + b"\n" * data[begin:stop].count(b"\n") + data[stop:]
    source.text = data.decode()


def _configs(element: ET.Element) -> dict[str, str]:
    return {c.get("key", ""): c.get("value", "") for c in element.findall("config")}


def _take_plugins(source: Source) -> None:
    """Remove top-level <plugin> elements, keeping every other line where it was."""
    spans: list[tuple[int, int, int]] = []  # (start byte, line, depth-1 start)
    parser = expat.ParserCreate()
    depth = 0
    starts: list[tuple[int, int]] = []
    data = source.text.encode()

    def start(tag: str, _attrs: dict[str, str]) -> None:
        nonlocal depth
        depth += 1
        if depth == 2 and tag == "plugin":
            starts.append((parser.CurrentByteIndex, parser.CurrentLineNumber))

    def end(tag: str) -> None:
        nonlocal depth
        if depth == 2 and tag == "plugin":
            begin, line = starts.pop()
            stop = parser.CurrentByteIndex  # at '</plugin>', or just after a '<plugin/>'
            if data.startswith(b"</", stop):
                stop = data.index(b">", stop) + 1
            spans.append((begin, stop, line))
        depth -= 1

    parser.StartElementHandler, parser.EndElementHandler = start, end
    try:
        parser.Parse(data, True)
    except expat.ExpatError as exc:
        raise LaunchError(f"{source.label}:{exc.lineno}:{exc.offset + 1}: not valid XML: "
                          f"{expat.ErrorString(exc.code)}") from None
    for begin, stop, line in reversed(spans):
        piece = data[begin:stop].decode()
        element = ET.fromstring(piece)
        filename = element.get("filename") or element.get("name") or ""
        source.plugins.insert(0, PluginConfig(filename, element.get("name", filename), element,
                                              f"{source.label}:{line}"))
        data = data[:begin] + b"\n" * piece.count("\n") + data[stop:]
    source.text = data.decode()


def compile_spec(source: Source, as_written: bool = False) -> mujoco.MjSpec:
    """Parse MJCF into a spec; MuJoCo's message keeps its line, with the file named.
    `as_written`: MuJoCo's own defaults where the file is silent (else an integrator the
    sim's servos need, see below)."""
    try:
        spec = mujoco.MjSpec.from_string(source.text, include=source.includes or None)
    except ValueError as exc:
        raise LaunchError(f"{source.label}: MuJoCo could not read it: {_clean(exc)}") from None
    if source.path is not None:
        spec.modelfiledir = str(source.path.parent)
    if not as_written and not re.search(r"\bintegrator\s*=", source.text):
        # Stable with the velocity actuators that wheels and joint servos use; Euler is not.
        spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    return spec


def _clean(exc: Exception) -> str:
    return " ".join(str(exc).split())
