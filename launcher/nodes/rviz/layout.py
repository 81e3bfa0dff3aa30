"""An rviz config (`.rviz`, rviz2's or ROS 1 rviz's) as a Foxglove layout (the JSON that
Foxglove's Layouts → Import takes).

The fixed frame becomes the 3D panel's followed frame. Displays map to Foxglove's panels:
- into the 3D panel: Grid (a grid layer: size, divisions, colour, offset), RobotModel (the
  URDF from its description topic), TF (the transforms), LaserScan, PointCloud2 and
  PointCloud (point size, flat colour or colour map, decay), Marker, MarkerArray, Odometry,
  Path, Pose, PoseArray, PoseWithCovariance, Polygon, Map (colour scheme, alpha) and
  InteractiveMarkers (their `/update` topic, drawn as markers: Foxglove does not interact);
- each Image and Camera display: an Image panel on its topic;
- Imu, FluidPressure, Temperature, Illuminance, RelativeHumidity and Range: a Plot panel of
  their values.
A display with no mapping is listed (once per class), as `unmapped`; so is a display with no
topic where it needs one.
"""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, Location
from launcher.user_files import check_yaml_depth, read_text

POINTS = {"LaserScan", "PointCloud2", "PointCloud"}
TOPICS_3D = {"Marker", "MarkerArray", "Odometry", "Path", "Pose", "PoseArray",
             "PoseWithCovariance", "Polygon", "Map", "GridCells", "Axes"}
IMAGES = {"Image", "Camera", "DepthCloud"}
PLOTTED = {"Imu": ["linear_acceleration.x", "linear_acceleration.y", "linear_acceleration.z"],
           "FluidPressure": ["fluid_pressure"], "Temperature": ["temperature"],
           "Illuminance": ["illuminance"], "RelativeHumidity": ["relative_humidity"],
           "Range": ["range"]}
GROUPS = {"Group"}


class RvizError(LaunchError):
    pass


def read(path: Path) -> dict[str, Any]:
    """The config's YAML; errors name file:line:column."""
    import yaml

    try:
        text = read_text(path)
    except OSError as exc:
        raise RvizError(f"cannot read the rviz config: {exc.strerror}",
                        Location(str(path))) from None
    except UnicodeDecodeError as exc:
        raise RvizError(f"not an rviz config: not UTF-8 text ({exc.reason} at byte "
                        f"{exc.start})", Location(str(path))) from None
    try:
        check_yaml_depth(text, str(path))
        document = yaml.safe_load(text)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        where = Location(str(path), mark.line + 1, mark.column + 1) if mark else \
            Location(str(path))
        raise RvizError(f"not an rviz config: the YAML does not parse ({exc.problem}); "
                        "expected the file rviz saves (File → Save Config)", where) from None
    if not isinstance(document, dict) or not isinstance(
            document.get("Visualization Manager"), dict):
        raise RvizError("not an rviz config: expected a map with 'Visualization Manager' "
                        "(the file rviz saves)", Location(str(path), 1, 1))
    return document


class Layout:
    """The layout being made: the 3D panel's settings, other panels, and what did not map."""

    def __init__(self) -> None:
        self.topics: dict[str, dict[str, Any]] = {}
        self.layers: dict[str, dict[str, Any]] = {}
        self.transforms: dict[str, Any] = {}
        self.images: list[str] = []
        self.plots: list[dict[str, Any]] = []
        self.unmapped: list[str] = []
        self._ids = itertools.count(1)

    def ident(self) -> str:
        return f"{next(self._ids):08x}"


def convert(document: dict[str, Any]) -> tuple[dict[str, Any], list[str]]:
    """(the Foxglove layout, the displays that did not map)."""
    manager = document["Visualization Manager"]
    options = manager.get("Global Options") or {}
    fixed = str(options.get("Fixed Frame") or "map")
    made = Layout()
    for display in _displays(manager.get("Displays") or []):
        _display(display, made)
    scene: dict[str, Any] = {"transforms": made.transforms} if made.transforms else {}
    background = _colour(options.get("Background Color"), 1.0)
    if background:
        scene["backgroundColor"] = background[:7]
    panels: list[tuple[str, dict[str, Any]]] = []
    three_d = {"followTf": fixed, "followMode": "follow-pose", "scene": scene,
               "topics": made.topics, "layers": made.layers}
    camera = _camera(manager.get("Views") or {})
    if camera:
        three_d["cameraState"] = camera
    panels.append((f"3D!{made.ident()}", three_d))
    for topic in made.images:
        panels.append((f"Image!{made.ident()}", {"imageMode": {"imageTopic": topic},
                                                 "cameraTopic": topic}))
    if made.plots:
        panels.append((f"Plot!{made.ident()}", {"paths": made.plots, "showLegend": True}))
    layout = {"configById": dict(panels), "globalVariables": {}, "userNodes": {},
              "playbackConfig": {"speed": 1}, "layout": _tree([p for p, _ in panels])}
    return layout, list(dict.fromkeys(made.unmapped))


def _displays(items: list[Any]) -> list[dict[str, Any]]:
    out: list[dict[str, Any]] = []
    for item in items:
        if not isinstance(item, dict):
            continue
        if _kind(item) in GROUPS:
            out += _displays(item.get("Displays") or [])
        else:
            out.append(item)
    return out


def _kind(display: dict[str, Any]) -> str:
    """`rviz_default_plugins/LaserScan`, `rviz/LaserScan`, `rviz_imu_plugin/Imu` → the last
    part."""
    return str(display.get("Class", "")).rsplit("/", 1)[-1]


def topic_of(display: dict[str, Any]) -> str | None:
    """The display's topic as rviz writes it: `Topic: /x`, or (rviz2) `Topic: {Value: /x}`,
    or ROS 1's own keys."""
    kind = _kind(display)
    if kind == "RobotModel":
        found = display.get("Description Topic") or display.get("Robot Description")
        value = found.get("Value") if isinstance(found, dict) else found
        if not value:
            return "/robot_description"
        return value if str(value).startswith("/") else f"/{value}"
    if kind == "InteractiveMarkers":
        namespace = display.get("Interactive Markers Namespace") or \
            display.get("Update Topic")
        namespace = namespace.get("Value") if isinstance(namespace, dict) else namespace
        if not namespace:
            return None
        return str(namespace) if str(namespace).endswith("/update") else \
            f"{namespace}/update"
    for key in ("Topic", "Image Topic", "Marker Topic"):
        value = display.get(key)
        if isinstance(value, dict):
            value = value.get("Value")
        if value:
            return str(value)
    return None


def _display(display: dict[str, Any], made: Layout) -> None:
    kind = _kind(display)
    enabled = bool(display.get("Enabled", display.get("Value", True)))
    name = str(display.get("Class", "?"))
    if kind == "Grid":
        _grid(display, enabled, made)
        return
    if kind == "TF":
        made.transforms.update({"visible": enabled,
                                "showLabel": bool(display.get("Show Names", True)),
                                "axisScale": float(display.get("Marker Scale", 1) or 1)})
        return
    if kind not in POINTS | TOPICS_3D | IMAGES | set(PLOTTED) | {"RobotModel",
                                                                "InteractiveMarkers"}:
        made.unmapped.append(name)
        return
    topic = topic_of(display)
    if topic is None:
        made.unmapped.append(f"{name} (no topic)")
    elif kind in POINTS:
        made.topics[topic] = _points(display, enabled)
    elif kind == "RobotModel":
        made.topics[topic] = {"visible": enabled}
        made.layers[made.ident()] = {"layerId": "foxglove.Urdf", "sourceType": "topic",
                                     "topic": topic, "visible": enabled,
                                     "label": str(display.get("Name", "RobotModel"))}
    elif kind in IMAGES:
        if topic not in made.images:
            made.images.append(topic)
    elif kind in PLOTTED:
        for field in PLOTTED[kind]:
            made.plots.append({"value": f"{topic}.{field}", "enabled": enabled,
                               "timestampMethod": "receiveTime"})
    else:  # TOPICS_3D and InteractiveMarkers
        made.topics[topic] = _shape(display, kind, enabled)


def _grid(display: dict[str, Any], enabled: bool, made: Layout) -> None:
    cell = float(display.get("Cell Size", 1) or 1)
    count = int(display.get("Plane Cell Count", 10) or 10)
    offset = display.get("Offset") or {}
    layer: dict[str, Any] = {
        "layerId": "foxglove.Grid", "visible": enabled, "size": cell * count,
        "divisions": count, "position": [float(offset.get(k, 0) or 0) for k in "XYZ"],
        "rotation": [0, 0, 0], "label": str(display.get("Name", "Grid"))}
    colour = _colour(display.get("Color"), display.get("Alpha", 1))
    if colour:
        layer["color"] = colour
    frame = str(display.get("Reference Frame", "<Fixed Frame>"))
    if frame != "<Fixed Frame>":
        layer["frameId"] = frame
    line = display.get("Line Style")
    if isinstance(line, dict) and line.get("Line Width"):
        layer["lineWidth"] = float(line["Line Width"])
    made.layers[made.ident()] = layer


def _points(display: dict[str, Any], enabled: bool) -> dict[str, Any]:
    settings: dict[str, Any] = {"visible": enabled,
                                "pointSize": float(display.get("Size (Pixels)", 2) or 2),
                                "decayTime": float(display.get("Decay Time", 0) or 0)}
    transformer = str(display.get("Color Transformer", "") or "")
    if transformer == "FlatColor":
        settings["colorMode"] = "flat"
        settings["flatColor"] = _colour(display.get("Color"), display.get("Alpha", 1)) or \
            "#ffffffff"
    else:
        settings["colorMode"] = "colormap"
        settings["colorMap"] = "rainbow" if display.get("Use rainbow", True) else "turbo"
        settings["colorField"] = str(display.get("Channel Name") or "intensity") \
            if transformer in ("Intensity", "") else {"AxisColor": "z"}.get(transformer, "x")
    return settings


def _shape(display: dict[str, Any], kind: str, enabled: bool) -> dict[str, Any]:
    settings: dict[str, Any] = {"visible": enabled}
    shape = display.get("Shape")
    colour = _colour((shape or {}).get("Color") if isinstance(shape, dict) else
                     display.get("Color"), display.get("Alpha", 1))
    if colour:
        settings["color"] = colour
    if kind in ("Odometry", "Pose", "PoseArray", "PoseWithCovariance"):
        style = (shape or {}).get("Value") if isinstance(shape, dict) else display.get("Shape")
        settings["type"] = "axis" if str(style).lower() == "axes" else "arrow"
    if kind == "Path" and display.get("Line Width"):
        settings["lineWidth"] = float(display["Line Width"])
    if kind == "Map":
        scheme = str(display.get("Color Scheme", "map")).lower()
        settings["colorMode"] = scheme if scheme in ("map", "costmap", "raw") else "map"
        settings["alpha"] = float(display.get("Alpha", 0.7) or 0.7)
    return settings


def _colour(text: Any, alpha: Any = 1.0) -> str | None:
    """rviz's "R; G; B" (and an alpha 0–1) as #rrggbbaa."""
    if not isinstance(text, str):
        return None
    try:
        red, green, blue = (max(0, min(255, int(float(p)))) for p in text.split(";"))
        opacity = max(0, min(255, round(float(alpha if alpha is not None else 1) * 255)))
    except ValueError:
        return None
    return f"#{red:02x}{green:02x}{blue:02x}{opacity:02x}"


def _camera(views: dict[str, Any]) -> dict[str, Any] | None:
    """rviz's orbit view (distance, focal point, pitch and yaw) as the 3D panel's camera."""
    import math

    current = views.get("Current") if isinstance(views, dict) else None
    if not isinstance(current, dict) or "Distance" not in current:
        return None
    focal = current.get("Focal Point") or {}
    try:
        return {"distance": float(current["Distance"]), "perspective": True,
                "phi": math.degrees(math.pi / 2 - float(current.get("Pitch", 0.785))),
                "thetaOffset": math.degrees(float(current.get("Yaw", 0.785))),
                "targetOffset": [float(focal.get(k, 0) or 0) for k in "XYZ"],
                "target": [0, 0, 0], "targetOrientation": [0, 0, 0, 1], "fovy": 45,
                "near": 0.01, "far": 5000}
    except (TypeError, ValueError):
        return None


def _tree(panels: list[str]) -> Any:
    """The panels side by side: the 3D panel at 60 %, the others stacked beside it."""
    if len(panels) == 1:
        return panels[0]
    rest: Any = panels[-1]
    for panel in reversed(panels[1:-1]):
        rest = {"first": panel, "second": rest, "direction": "column"}
    return {"first": panels[0], "second": rest, "direction": "row", "splitPercentage": 60}


def write(layout: dict[str, Any], path: Path) -> None:
    """The layout as JSON, 0600 (it names the user's topics and frames); a folder made for it
    is 0700, and an existing one is left as it is."""
    import json
    import os

    if not path.parent.exists():
        path.parent.mkdir(parents=True)
        os.chmod(path.parent, 0o700)
    descriptor = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(descriptor, "w", encoding="utf-8") as handle:
        json.dump(layout, handle, indent=2)
        handle.write("\n")
