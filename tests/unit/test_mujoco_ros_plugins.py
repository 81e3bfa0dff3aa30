"""mujoco_ros2_control's ROS plugins without a bus: their parameters declared as data and read
under their prefix, and their work on the grid of sim/schedule.py."""

from __future__ import annotations

from types import SimpleNamespace

import mujoco
import pytest

from launcher.bus.node_parameters import NodeParameters
from launcher.errors import LaunchError
from launcher.sim.mujoco_control.camera_plugin import CameraPlugin
from launcher.sim.mujoco_control.ros_plugin import scoped
from launcher.sim.mujoco_control.ros_plugins import PREFIX, load_plugins

CYCLE = 0.01  # s: a control cycle at controller_manager's 100 Hz

SCENE = """<mujoco><worldbody>
  <camera name="front" pos="0 0 1"/><camera name="rear" pos="0 0 1"/>
  <body name="box"><freejoint/><geom type="box" size="0.1 0.1 0.1"/></body>
</worldbody></mujoco>"""


class Node:
    """Stands in for the mujoco_ros2_control_node: real parameters, recorded endpoints."""

    def __init__(self, parameters: dict) -> None:
        self.params = NodeParameters(dict(parameters), "/mujoco_ros2_control_node")
        self.published: dict[str, list] = {}
        self.services: dict[str, object] = {}
        self.logged: list[str] = []

    @property
    def parameters(self) -> dict:
        return self.params.values

    def get_logger(self):
        say = self.logged.append
        return SimpleNamespace(info=say, warning=say, error=say)

    def create_publisher(self, type_name, topic, qos):
        box = self.published.setdefault(topic, [])
        return SimpleNamespace(publish=box.append, get_subscription_count=lambda: 1,
                               name=topic)

    def create_service(self, type_name, name, callback):
        self.services[name] = callback
        return SimpleNamespace(name=name, deferred=False)

    def create_subscription(self, type_name, topic, callback, qos):
        return SimpleNamespace()

    def message(self, type_name, **fields):
        return SimpleNamespace(**fields)


class Rendering:
    """Stands in for the sim's renderer link: records what it is asked to draw."""

    def __init__(self) -> None:
        self.cameras: list[str] = []
        self.drawn: list[list[str]] = []

    def add(self, camera) -> None:
        self.cameras.append(camera.camera_name)

    def wants(self, camera: str) -> bool:
        return True

    def request(self, cameras: list[str], data) -> None:
        self.drawn.append(cameras)

    def sync(self, model) -> None:
        pass


def world() -> SimpleNamespace:
    model = mujoco.MjModel.from_xml_string(SCENE)
    return SimpleNamespace(model=model, data=mujoco.MjData(model), rendering=Rendering(),
                           plugins=SimpleNamespace(world=[]))


def plugin(kind: str, files: list[str] | None = None, **settings):
    """One plugin `p` of `kind`, with `settings` under its name, made as the node makes it."""
    node = Node({"mujoco_plugins.p.type": f"{PREFIX}{kind}",
                 **{f"mujoco_plugins.p.{k}": v for k, v in settings.items()}})
    return load_plugins(node, world(), "robot.urdf:7", files)[0]


def cycles(found, seconds: float) -> None:
    for step in range(1, round(seconds / CYCLE) + 1):
        found.update(found.world.model, found.world.data, step * CYCLE)


@pytest.mark.parametrize("rate", [0, -1.0])
def test_a_rate_of_zero_or_less_is_refused_at_its_line_not_divided_by(tmp_path, rate):
    written = tmp_path / "plugins.yaml"
    written.write_text("/**:\n  ros__parameters:\n    mujoco_plugins:\n      p:\n"
                       "        type: mujoco_ros2_control_plugins/HeartbeatPublisherPlugin\n"
                       f"        update_rate: {rate}\n")
    with pytest.raises(LaunchError) as raised:
        plugin("HeartbeatPublisherPlugin", [str(written)], update_rate=rate)
    assert str(raised.value).startswith(f"{written}:6: ")
    assert "'mujoco_plugins.p.update_rate': expected a number > 0" in str(raised.value)


def test_a_rate_that_is_no_multiple_of_the_control_cycle_keeps_its_average():
    beat = plugin("HeartbeatPublisherPlugin", update_rate=30.0)
    cycles(beat, 10.0)
    assert len(beat.node.published["/p/mujoco_heartbeat"]) in (300, 301)  # last + 1/30: 250


def test_declared_parameters_are_listed_with_their_defaults_and_described():
    node = Node({"mujoco_plugins.beat.type": f"{PREFIX}HeartbeatPublisherPlugin",
                 "mujoco_plugins.push.type": f"{PREFIX}ExternalWrenchPlugin",
                 "mujoco_plugins.push.force_arrow_scale": 0.02})
    load_plugins(node, world(), "robot.urdf:7")
    assert node.parameters["mujoco_plugins.beat.update_rate"] == 1.0
    assert node.parameters["mujoco_plugins.push.torque_arrow_scale"] == 0.1
    assert node.parameters["mujoco_plugins.push.force_arrow_scale"] == 0.02
    for name in ("mujoco_plugins.beat.update_rate", "mujoco_plugins.push.force_arrow_scale"):
        assert node.params.describe(name)["description"], name  # every plugin's, not the last's


def test_a_value_of_the_wrong_type_is_refused_with_the_parameter_named():
    with pytest.raises(LaunchError, match=r"robot.urdf:7: .*'mujoco_plugins.p.body': expected "
                                          r"text"):
        plugin("BaseVelocityPlugin", body=3)


def test_a_placeholder_stands_for_each_name_and_fills_its_text_default():
    found = {p.name: p.default for p in scoped(CameraPlugin.PARAMETERS, "c.",
                                               {"camera": ["front", "rear"]}, {})}
    assert found["c.camera_publish_rate"] == 5.0
    assert found["c.front.frame_name"] == "front_frame" and found["c.rear.depth_topic"] == \
        "rear/depth"
    assert not any("{" in name for name in found)


def test_the_camera_plugin_reads_each_camera_under_its_fixed_prefix_and_streams_on_the_grid():
    node = Node({"mujoco_plugins.cams.type": f"{PREFIX}CameraPlugin",
                 "mujoco_plugins.mujoco_camera_plugin.camera_publish_rate": 30.0,
                 "mujoco_plugins.mujoco_camera_plugin.rear.policy": "disabled",
                 "mujoco_plugins.mujoco_camera_plugin.front.frame_name": "optical"})
    cameras = load_plugins(node, world(), "robot.urdf:7")[0]
    assert cameras.world.rendering.cameras == ["front"]
    assert cameras.cameras[0].frame == "optical"
    assert cameras.cameras[0].topics["image"] == "/cams/front/color"
    cycles(cameras, 1.0)
    assert len(cameras.world.rendering.drawn) in (30, 31)


def test_a_camera_policy_that_is_none_of_the_three_is_refused_with_the_nearest():
    node = Node({"mujoco_plugins.cams.type": f"{PREFIX}CameraPlugin",
                 "mujoco_plugins.mujoco_camera_plugin.front.policy": "poled"})
    with pytest.raises(LaunchError, match=r"expected one of streaming, polled, disabled, got "
                                          r"'poled' \(did you mean 'polled'"):
        load_plugins(node, world(), "robot.urdf:7")
