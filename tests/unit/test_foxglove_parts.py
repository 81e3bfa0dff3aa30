"""The foxglove bridge's parts that need no server: the schemas it advertises (types.py's
definitions), its asset rules (assets.py), and its settings' errors."""

from __future__ import annotations

import pytest

from launcher.bus.node_parameters import NodeParameters
from launcher.bus.types import registry
from launcher.errors import LaunchError
from launcher.nodes.foxglove.assets import DEFAULT_ALLOWLIST, Assets
from launcher.nodes.foxglove.settings import Settings

VIEWED = ["visualization_msgs/msg/Marker", "visualization_msgs/msg/MarkerArray",
          "nav_msgs/msg/Path", "nav_msgs/msg/OccupancyGrid", "nav_msgs/msg/Odometry",
          "geometry_msgs/msg/PoseArray", "sensor_msgs/msg/Image",
          "sensor_msgs/msg/CompressedImage", "sensor_msgs/msg/CameraInfo",
          "sensor_msgs/msg/LaserScan", "sensor_msgs/msg/PointCloud2", "sensor_msgs/msg/Imu",
          "sensor_msgs/msg/NavSatFix", "sensor_msgs/msg/MagneticField",
          "sensor_msgs/msg/FluidPressure", "geometry_msgs/msg/WrenchStamped",
          "tf2_msgs/msg/TFMessage", "std_msgs/msg/String"]


@pytest.mark.parametrize("name", VIEWED)
def test_the_types_a_view_shows_have_full_schemas(name):
    text = registry().definition(name)
    fields = registry().fields(name)
    assert text.split("\n=====", 1)[0].count("\n") >= len(fields) - 1
    named = {f"MSG: {d.rsplit('/', 1)[0].replace('/msg', '')}/{d.rsplit('/', 1)[1]}"
             for d in _nested(name)}
    assert all(line in text for line in named), (name, named - set(text.splitlines()))


def _nested(name: str, seen: set[str] | None = None) -> set[str]:
    seen = set() if seen is None else seen
    for _, kind in registry().fields(name):
        for part in _names(kind):
            if part not in seen:
                seen.add(part)
                _nested(part, seen)
    return seen


def _names(kind: object) -> list[str]:
    if isinstance(kind, str) and kind.count("/") == 2:
        return [kind]
    if isinstance(kind, tuple | list):
        return [n for item in kind for n in _names(item)]
    return []


def test_assets_stay_inside_their_package_and_the_allowlist(tmp_path):
    share = tmp_path / "robot"
    (share / "meshes").mkdir(parents=True)
    (share / "meshes" / "base.stl").write_bytes(b"solid base")
    (share / "meshes" / "notes.txt").write_text("not a mesh")
    (tmp_path / "secret.stl").write_bytes(b"outside")
    (share / "meshes" / "link.stl").symlink_to(tmp_path / "secret.stl")

    class Packages:
        def share(self, name):
            if name != "robot":
                raise LaunchError(f"package '{name}' not found")
            return share

    assets = Assets(DEFAULT_ALLOWLIST, Packages())
    assert assets.fetch("package://robot/meshes/base.stl") == b"solid base"
    assert assets.fetch("package://robot/meshes/notes.txt") is None  # not allowed
    assert assets.fetch("package://robot/../secret.stl") is None
    assert assets.fetch("package://robot/meshes/../../secret.stl") is None
    assert assets.fetch("package://robot/meshes/link.stl") is None  # a link out of it
    assert assets.fetch("package://other/meshes/base.stl") is None
    assert assets.fetch("file:///etc/passwd") is None
    assert assets.fetch("package://robot/meshes/missing.stl") is None
    anything = Assets([r".*"], Packages())
    assert anything.fetch("package://robot/meshes/notes.txt") == b"not a mesh"


class FakeNode:
    """A node with its real parameters and nothing else."""

    def __init__(self, values):
        self.params = NodeParameters(dict(values), "/foxglove_bridge")


@pytest.mark.parametrize("values, expected", [
    ({"topic_whitelist": ["(unclosed"]}, "topic_whitelist: '(unclosed' is not a regular"),
    ({"capabilities": ["clientPublish", "teleport"]},
     "/foxglove_bridge: parameter 'capabilities': expected one of clientPublish, parameters, "
     "parametersSubscribe, services, connectionGraph, assets, got 'teleport'"),
    ({"port": 70000}, "/foxglove_bridge: parameter 'port': expected a number ≤ 65535, got 70000"),
    ({"max_qos_depth": "deep"},
     "/foxglove_bridge: parameter 'max_qos_depth': expected a whole number, got 'deep'"),
])
def test_bad_settings_are_said(values, expected):
    with pytest.raises(LaunchError, match=expected.replace("(", r"\(").replace("[", r"\[")):
        Settings(FakeNode(values))


def test_settings_defaults_are_foxglove_bridges():
    settings = Settings(FakeNode({}))
    assert (settings.port, settings.address, settings.max_qos_depth) == (8765, "127.0.0.1", 25)
    assert settings.backlog == 19 and settings.token is True
    assert "assets" in settings.capabilities


def test_whitelists_and_hidden_names_choose_what_is_served():
    from launcher.nodes.foxglove.bridge import Bridge

    bridge = Bridge.__new__(Bridge)
    bridge.settings = Settings(FakeNode({"topic_whitelist": ["/odom", "/camera/.*"]}))
    shown = [t for t in ("/odom", "/odom/extra", "/camera/image", "/tf",
                         "/camera/_private/x") if bridge._shown(t, bridge.settings.topics)]
    assert shown == ["/odom", "/camera/image"]  # whole-name matches; hidden names left out
    bridge.settings = Settings(FakeNode({"include_hidden": True}))
    assert bridge._shown("/fibonacci/_action/status", bridge.settings.topics)
