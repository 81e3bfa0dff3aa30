"""ros2_control's pieces on their own: the URDF's <ros2_control> blocks, trajectories as
joint_trajectory_controller samples them, and the manager's switching rules over mock
hardware (a stand-in node: no bus)."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from launcher.bus.node_parameters import NodeParameters
from launcher.control.controller import Controller
from launcher.control.controllers.trajectory import Point, Trajectory, validate
from launcher.control.description import parse
from launcher.control.hardware import GenericSystem
from launcher.control.manager import BEST_EFFORT, STRICT, ControllerManager
from launcher.control.yaml_places import Places, block_place, params_files, value_place
from launcher.errors import LaunchError
from launcher.lifecycle import ACTIVE, FINALIZED, INACTIVE, UNCONFIGURED

URDF = """<robot name="r">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="revolute"><parent link="a"/><child link="b"/></joint>
  <joint name="j2" type="revolute"><parent link="b"/><child link="c"/>
    <mimic joint="j1" multiplier="-2" offset="0.1"/></joint>
  <ros2_control name="Hw" type="system">
    <hardware><plugin>{plugin}</plugin></hardware>
    <joint name="j1">
      <command_interface name="position"><param name="min">-1</param>
        <param name="max">1</param></command_interface>
      <command_interface name="velocity"/>
      <state_interface name="position"><param name="initial_value">0.5</param>
        </state_interface>
      <state_interface name="velocity"/>
    </joint>
    <joint name="j2"><state_interface name="position"/></joint>
  </ros2_control>
</robot>"""


def test_ros2_control_blocks_are_read_with_limits_initial_values_and_mimics():
    (hardware,) = parse(URDF.format(plugin="mock_components/GenericSystem"), "r.urdf")
    assert (hardware.name, hardware.type, hardware.where) == ("Hw", "system", "r.urdf:6")
    assert hardware.command_names() == ["j1/position", "j1/velocity"]
    assert hardware.state_names() == ["j1/position", "j1/velocity", "j2/position"]
    position = hardware.joints[0].command_interfaces[0]
    assert (position.min, position.max) == (-1.0, 1.0)
    assert hardware.joints[0].state_interfaces[0].initial_value == 0.5
    assert hardware.joints[1].mimic == ("j1", -2.0, 0.1)


def test_an_unknown_hardware_plugin_or_joint_is_located_and_explained():
    with pytest.raises(LaunchError) as caught:
        parse(URDF.format(plugin="gz_ros2_control/GazeboSimSytem"), "r.urdf")
    assert str(caught.value).startswith("r.urdf:6: <ros2_control name=\"Hw\">: unknown "
                                        "hardware plugin 'gz_ros2_control/GazeboSimSytem'")
    assert "did you mean 'gz_ros2_control/GazeboSimSystem'" in str(caught.value)
    with pytest.raises(LaunchError, match="joint 'j9' is not a joint of the URDF"):
        parse(URDF.format(plugin="mock_components/GenericSystem").replace(
            '<joint name="j2"><state', '<joint name="j9"><state'), "r.urdf")


def test_mock_hardware_follows_commands_and_mimics():
    (hardware,) = parse(URDF.format(plugin="mock_components/GenericSystem"), "r.urdf")
    system = GenericSystem(hardware)
    assert system.states["j1/position"].value == 0.5
    assert system.commands["j1/position"].value == 0.5  # a position command starts held
    system.commands["j1/position"].value = 0.25
    system.read(0.0, 0.01)
    assert system.states["j1/position"].value == 0.25
    assert system.states["j2/position"].value == pytest.approx(0.25 * -2 + 0.1)


def test_trajectories_are_validated_as_joint_trajectory_controller_does():
    joints = ["a", "b"]
    good = [Point(1.0, [0, 0]), Point(2.0, [1, 1])]
    assert validate(["b", "a"], joints, good, partial=False) == ""
    assert "not controlled" in validate(["a", "x"], joints, good, False)
    assert "expected all of" in validate(["a"], joints, [Point(1.0, [0])], False)
    assert validate(["a"], joints, [Point(1.0, [0])], True) == ""
    assert "must increase" in validate(joints, joints, [Point(2.0, [0, 0]), Point(2.0, [1, 1])],
                                       False)
    assert "NaN" in validate(joints, joints, [Point(1.0, [math.nan, 0])], False)
    assert "has 1 positions for 2 joints" in validate(joints, joints, [Point(1.0, [0])], False)


def test_trajectories_are_sampled_along_lines_cubics_and_quintics():
    line = Trajectory(Point(0.0, [0.0]), [Point(2.0, [2.0])])
    assert line.sample(1.0) == ([1.0], [1.0], [0.0])
    assert line.sample(5.0)[0] == [2.0]
    cubic = Trajectory(Point(0.0, [0.0], [0.0]), [Point(1.0, [1.0], [0.0])])
    p, v, _ = cubic.sample(0.5)
    assert p[0] == pytest.approx(0.5) and v[0] == pytest.approx(1.5)
    assert cubic.sample(0.999)[1][0] == pytest.approx(0.0, abs=0.01)  # arrives at rest
    quintic = Trajectory(Point(0.0, [0.0], [0.0], [0.0]), [Point(1.0, [1.0], [0.0], [0.0])])
    p, v, a = quintic.sample(0.5)
    assert p[0] == pytest.approx(0.5) and v[0] == pytest.approx(1.875)
    assert quintic.sample(1e-6)[2][0] == pytest.approx(0.0, abs=1e-3)
    held = Trajectory(Point(0.0, [0.0]), [Point(1.0, [1.0]), Point(2.0, [3.0])], False)
    assert held.sample(1.5)[0] == [1.0]


class StandIn:
    """The part of a bus node the manager uses, with no bus."""

    def __init__(self, parameters: dict) -> None:
        self.parameters, self.name, self.namespace = parameters, "controller_manager", ""
        self.params = NodeParameters(parameters, self.name)
        self.logged: list[str] = []
        log = SimpleNamespace(info=self.logged.append, error=self.logged.append,
                              warning=self.logged.append)
        self.get_logger = lambda: log
        self.create_service = lambda *a, **k: None
        self.message = lambda type_name, **fields: SimpleNamespace(**fields)
        self.destroy_node = lambda: None


class Servo(Controller):
    def __init__(self, name: str, interfaces: list[str], parameters: dict | None = None) -> None:
        super().__init__(name, StandIn(parameters or {}), "test/Servo", Places())
        self.wanted = interfaces
        self.state = INACTIVE

    def command_interfaces(self) -> list[str]:
        return self.wanted


def _manager() -> ControllerManager:
    (hardware,) = parse(URDF.format(plugin="mock_components/GenericSystem"), "r.urdf")
    manager = ControllerManager(StandIn({"update_rate": 200}), [GenericSystem(hardware)], [])
    for name, interfaces in (("a", ["j1/position"]), ("b", ["j1/position"]),
                             ("c", ["j1/velocity"]), ("d", ["j7/position"])):
        manager.controllers[name] = Servo(name, interfaces)
    return manager


def test_the_managers_update_rate_is_refused_at_its_line_when_it_is_not_a_whole_number(
        tmp_path):
    (hardware,) = parse(URDF.format(plugin="mock_components/GenericSystem"), "r.urdf")
    params = tmp_path / "controllers.yaml"
    params.write_text("controller_manager:\n  ros__parameters:\n    update_rate: fast\n")
    with pytest.raises(LaunchError) as caught:
        ControllerManager(StandIn({"update_rate": "fast"}), [GenericSystem(hardware)],
                          [str(params)])
    assert str(caught.value) == (f"{params}:3: controller_manager: parameter 'update_rate': "
                                 "expected a whole number, got 'fast'")


def test_a_claimed_interface_is_never_claimed_twice_and_the_running_one_keeps_running():
    manager = _manager()
    assert manager.update_rate == 200
    assert manager.switch(["a"], [])[0]
    ok, message = manager.switch(["b"], [], STRICT)
    assert not ok and "'j1/position' is currently claimed by another controller ('a')" in message
    assert manager.controllers["a"].state == ACTIVE
    ok, message = manager.switch(["b", "c"], [], STRICT)  # strict: nothing happens
    assert not ok and manager.controllers["c"].state == INACTIVE
    ok, _ = manager.switch(["b", "c"], [], BEST_EFFORT)  # best effort: what can be done
    assert ok and manager.controllers["c"].state == ACTIVE
    assert manager.switch(["b"], ["a"], STRICT)[0]  # one step: a out, b in
    assert manager.resources.claimed["j1/position"] == "b"
    ok, message = manager.switch(["d"], [], STRICT)
    assert not ok and "'j7/position' is not available" in message
    assert "did you mean 'j1/position'" in message
    ok, message = manager.switch(["zz"], [], STRICT)
    assert not ok and "no controller with this name exists" in message


def test_requests_move_a_controller_only_as_the_lifecycle_table_allows():
    manager = _manager()
    servo = manager.controllers["a"]
    assert manager.cleanup("a") == (True, "") and servo.state == UNCONFIGURED
    assert manager.cleanup("a") == (
        False, "Controller 'a' can not be cleaned-up from 'unconfigured' state.")
    assert manager.configure("a") == (True, "") and servo.state == INACTIVE
    assert manager.configure("a") == (True, "")  # again: cleaned up first
    assert manager.switch(["a"], [])[0] and servo.state == ACTIVE
    assert manager.configure("a") == (
        False, "Controller 'a' can not be configured from 'active' state.")
    assert manager.unload("a") == (
        False, "Could not unload controller with name 'a' because it is still active")
    assert manager.switch([], ["a"])[0]
    assert manager.unload("a") == (True, "") and "a" not in manager.controllers
    assert servo.state == FINALIZED
    assert manager.unload("a") == (False, "Could not unload controller with name 'a' because "
                                          "no controller with this name exists")


def test_a_controllers_update_rate_is_declared_and_read_as_it_is_configured():
    manager = _manager()
    manager.controllers["e"] = Servo("e", [], {"update_rate": 50})
    manager.controllers["f"] = Servo("f", [], {"update_rate": "fast"})
    for servo in (manager.controllers["e"], manager.controllers["f"]):
        servo.state = UNCONFIGURED
    assert manager.configure("e") == (True, "") and manager.controllers["e"].update_rate == 50
    ok, message = manager.configure("f")
    assert not ok and "parameter 'update_rate'" in message
    assert manager.controllers["f"].state == UNCONFIGURED
    assert manager.controllers["f"].update_rate == 0


def test_a_controller_is_made_with_its_type_name_and_places(tmp_path):
    params = tmp_path / "controllers.yaml"
    params.write_text("arm:\n  ros__parameters:\n    joints: [j1]\n")
    places = Places.find([str(params)], "arm")
    servo = Controller("arm", StandIn({}), "test/Servo", places)
    assert servo.type_name == "test/Servo" and places.block == f"{params}:1"
    assert places.key("joints") == f"{params}:3"
    assert places.value(["j1"]) == f"{params}:3:14"


def test_params_file_values_and_controller_blocks_are_found(tmp_path):
    assert params_files("['/a.yaml', '/b.yaml']") == ["/a.yaml", "/b.yaml"]
    assert params_files("/a.yaml") == ["/a.yaml"]
    assert params_files(["/a.yaml"]) == ["/a.yaml"]
    assert params_files("") == []
    path = tmp_path / "c.yaml"
    path.write_text("x:\n  ros__parameters: {}\n/**:\n  /arm:\n    ros__parameters: {}\n")
    assert block_place([str(path)], "x") == f"{path}:1"
    assert block_place([str(path)], "arm") == f"{path}:4"
    assert block_place([str(path)], "nope") == ""


@pytest.mark.parametrize("names", [["a", "bc", "def"], [], ["j1"]])
def test_joint_states_packed_directly_are_the_serializers_bytes(names):
    from launcher.bus.types import registry
    from launcher.bus.wire import JointStateLayout

    count = len(names)
    packed = JointStateLayout(names).pack(5, 7, [1.0] * count, [2.0] * count, [3.0] * count)
    message = registry().deserialize(packed, "sensor_msgs/msg/JointState")
    assert list(message.name) == names and list(message.velocity) == [2.0] * count
    assert (message.header.stamp.sec, message.header.stamp.nanosec) == (5, 7)
    assert registry().serialize(message, "sensor_msgs/msg/JointState") == packed


def test_a_missing_interface_is_placed_at_the_joint_that_asked_for_it(tmp_path):
    params = tmp_path / "controllers.yaml"
    params.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
                      "jtc:\n  ros__parameters:\n    joints:\n      - j1\n      - nope\n"
                      "    interface_name: position\n")
    assert value_place([str(params)], "jtc", ["nope/position", "nope", "position"]) == \
        f"{params}:8:9"
    assert value_place([str(params)], "jtc", ["j9/effort", "j9", "effort"]) == ""
