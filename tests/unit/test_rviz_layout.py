"""rviz configs as Foxglove layouts (nodes/rviz/layout.py): ros_gz_sim_demos' and
mujoco_ros2_control_demos' configs, in place, each converted and checked against the .rviz
file as read here."""

from __future__ import annotations

import json
import subprocess

import pytest
import yaml

from launcher.nodes.rviz import layout
from tests.support.environment import shared
from tests.support.processes import launcher_argv

CONFIGS = [("ros_gz_sim_demos", "rviz", name) for name in
           ("camera.rviz", "diff_drive.rviz", "gpu_lidar_bridge.rviz", "imu.rviz")] + \
    [("mujoco_ros2_control", "mujoco_ros2_control_demos", "config", "test_robot.rviz")]


def displays(document: dict) -> list[tuple[str, str | None]]:
    """(class's last part, topic) of each display, as the test reads the file."""
    out = []
    for display in document["Visualization Manager"]["Displays"]:
        topic = display.get("Topic", display.get("Description Topic"))
        out.append((display["Class"].rsplit("/", 1)[-1],
                    topic.get("Value") if isinstance(topic, dict) else topic))
    return out


@pytest.mark.parametrize("place", CONFIGS, ids=lambda place: place[-1])
def test_the_demos_configs_convert_with_their_frame_panels_and_topics(place):
    path = shared("external", *place)
    document = yaml.safe_load(path.read_text())
    made, unmapped = layout.convert(layout.read(path))
    assert unmapped == []
    panels = made["configById"]
    three_d = next(v for k, v in panels.items() if k.startswith("3D!"))
    assert three_d["followTf"] == document["Visualization Manager"]["Global Options"][
        "Fixed Frame"]
    images = [v["imageMode"]["imageTopic"] for k, v in panels.items() if k.startswith("Image!")]
    plotted = [p["value"] for k, v in panels.items() if k.startswith("Plot!")
               for p in v["paths"]]
    grids = [layer for layer in three_d["layers"].values()
             if layer["layerId"] == "foxglove.Grid"]
    for kind, topic in displays(document):
        if kind == "Grid":
            assert grids and grids[0]["divisions"] == 10 and grids[0]["size"] == 10
        elif kind in ("Image", "Camera"):
            assert topic in images
        elif kind == "Imu":
            assert f"{topic}.linear_acceleration.x" in plotted
        elif kind == "TF":  # (the 3D panel draws every frame of /tf)
            continue
        elif kind == "RobotModel":
            assert any(layer["layerId"] == "foxglove.Urdf" and layer["topic"] == topic
                       for layer in three_d["layers"].values())
        else:
            assert three_d["topics"][topic]["visible"] is True, (kind, topic)
    # the panels side by side in the layout tree
    tree = json.dumps(made["layout"])
    assert all(key in tree for key in panels)


def test_colours_points_and_an_unknown_display():
    document = {"Visualization Manager": {
        "Global Options": {"Fixed Frame": "odom", "Background Color": "48; 48; 48"},
        "Displays": [
            {"Class": "rviz_default_plugins/LaserScan", "Topic": {"Value": "/scan"},
             "Color Transformer": "FlatColor", "Color": "255; 0; 0", "Alpha": 0.5,
             "Size (Pixels)": 4, "Enabled": True},
            {"Class": "rviz_common/Group", "Displays": [
                {"Class": "rviz_default_plugins/MarkerArray", "Topic": "/markers",
                 "Enabled": False},
                {"Class": "rviz_default_plugins/RobotModel",
                 "Description Topic": {"Value": "/robot_description"}}]},
            {"Class": "rviz_default_plugins/InteractiveMarkers",
             "Interactive Markers Namespace": "/controls"},
            {"Class": "some_vendor/Hologram", "Topic": "/h"},
            {"Class": "some_vendor/Hologram", "Topic": "/h2"},
            {"Class": "rviz_default_plugins/Path"}]}}
    made, unmapped = layout.convert(document)
    three_d = next(iter(made["configById"].values()))
    assert three_d["topics"]["/scan"] == {"visible": True, "pointSize": 4.0, "decayTime": 0.0,
                                          "colorMode": "flat", "flatColor": "#ff000080"}
    assert three_d["topics"]["/markers"]["visible"] is False  # inside a group, disabled
    assert three_d["topics"]["/controls/update"]["visible"] is True
    urdf = [layer for layer in three_d["layers"].values() if layer["layerId"] ==
            "foxglove.Urdf"]
    assert urdf and urdf[0]["topic"] == "/robot_description"
    assert three_d["scene"]["backgroundColor"] == "#303030"
    assert unmapped == ["some_vendor/Hologram", "rviz_default_plugins/Path (no topic)"]


def test_rviz2_layout_writes_the_file_and_says_where_a_config_is_wrong(tmp_path):
    config = shared("external", "ros_gz_sim_demos", "rviz", "camera.rviz")
    target = tmp_path / "out" / "camera.json"
    done = subprocess.run([*launcher_argv(), "rviz2-layout", str(config), "-o", str(target)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == f"{target}: 3D, Image"
    assert json.loads(target.read_text())["configById"]
    assert target.stat().st_mode & 0o777 == 0o600
    assert target.parent.stat().st_mode & 0o777 == 0o700  # made for it: private
    shared_folder = tmp_path / "shared"
    shared_folder.mkdir(mode=0o755)
    shared_folder.chmod(0o755)
    done = subprocess.run([*launcher_argv(), "rviz2-layout", str(config), "-o",
                           str(shared_folder / "c.json")], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert shared_folder.stat().st_mode & 0o777 == 0o755  # a folder of the user's: untouched
    broken = tmp_path / "broken.rviz"
    broken.write_text("Panels:\n  - Class: x\nVisualization Manager: [1, 2\n")
    done = subprocess.run([*launcher_argv(), "rviz2-layout", str(broken)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert f"{broken}:4:1: not an rviz config: the YAML does not parse" in done.stderr
    other = tmp_path / "other.rviz"
    other.write_text("just: a map\n")
    done = subprocess.run([*launcher_argv(), "rviz2-layout", str(other)],
                          capture_output=True, text=True, timeout=60)
    assert f"{other}:1:1: not an rviz config: expected a map with 'Visualization Manager'" \
        in done.stderr


@pytest.mark.parametrize("text, expected", [
    ("Visualization Manager:\n  Displays:\n" +
     "".join("  " * (i + 2) + "- a:\n" for i in range(3000)),
     ":52:103: nested 101 levels deep; launcher reads YAML nested up to 100 levels"),
    ("a: " + "[" * 5000 + "]" * 5000,
     ":1:1003: not an rviz config: the YAML does not parse (exceeded maximum nesting depth)"),
], ids=["block", "flow"])
def test_an_rviz_config_nested_thousands_deep_is_refused_at_its_place(tmp_path, text, expected):
    """(It was `internal error: RecursionError`.)"""
    deep = tmp_path / "deep.rviz"
    deep.write_text(text)
    done = subprocess.run([*launcher_argv(), "rviz2-layout", str(deep), "-o",
                           str(tmp_path / "out.json")], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 1
    assert f"{deep}{expected}" in done.stderr, done.stderr
    assert "internal error" not in done.stderr and "Traceback" not in done.stderr
