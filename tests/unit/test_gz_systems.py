"""Gazebo's motion and pose systems on the sim (a stand-in bus that records): ApplyJointForce,
VelocityControl, OdometryPublisher and PosePublisher, as gz-sim documents them."""

from __future__ import annotations

import itertools
import math
from types import SimpleNamespace

import pytest

from launcher.sim.entity import SpawnError
from tests.support.sim import IDENTITY, make_world

VEHICLE = """<?xml version="1.0"?><sdf version="1.9"><model name="vehicle">
  <link name="chassis"><inertial><mass>10</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz>
  </inertia></inertial><collision name="c"><geometry><box><size>1 0.6 0.2</size></box>
  </geometry></collision></link>
  <link name="flag"><pose>0.3 0 0.3 0 0 0</pose><inertial><mass>0.5</mass><inertia>
  <ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>
  <joint name="flag_hinge" type="revolute"><parent>chassis</parent><child>flag</child>
  <axis><xyz>0 0 1</xyz></axis></joint>
  {plugins}
</model></sdf>"""


def spawn(world, plugins: str, z: float = 0.2):
    return world.spawn(world.templates.from_string(VEHICLE.format(plugins=plugins)), "vehicle",
                       [0, 0, z], IDENTITY)


def run(world, seconds: float) -> None:
    end = world.data.time + seconds
    while world.data.time < end - 1e-9:
        world.physics.step(world.physics.steps_until_update(100))


def hinge_speed(world) -> float:
    return float(world.data.qvel[world.model.joint("vehicle/flag_hinge").dofadr[0]])


def test_apply_joint_force_turns_the_joint_until_told_otherwise():
    world = make_world()
    spawn(world, '<plugin filename="gz-sim-apply-joint-force-system" '
                 'name="gz::sim::systems::ApplyJointForce"><joint_name>flag_hinge</joint_name>'
                 '</plugin>')
    topic = "/model/vehicle/joint/flag_hinge/cmd_force"
    world.transport.callbacks[topic](SimpleNamespace(data=0.5))
    run(world, 0.5)
    assert hinge_speed(world) > 1.0  # 0.5 N·m on ~0.01 kg·m²
    world.transport.callbacks[topic](SimpleNamespace(data=float("nan")))  # ignored, said
    assert any("not finite" in m for m in world.transport.messages("warning"))


def test_apply_joint_force_names_a_missing_joint():
    world = make_world()
    with pytest.raises(SpawnError, match=r"<string>:9: .*'elbow' is not in the model "
                                         r"\(joints: flag_hinge\)"):
        spawn(world, '<plugin filename="libignition-gazebo-apply-joint-force-system.so" '
                     'name="ignition::gazebo::systems::ApplyJointForce"><joint_name>elbow'
                     '</joint_name></plugin>')


def twist(x: float = 0.0, yaw: float = 0.0):
    return SimpleNamespace(linear=SimpleNamespace(x=x, y=0.0, z=0.0),
                           angular=SimpleNamespace(x=0.0, y=0.0, z=yaw))


SYSTEMS = """<plugin filename="gz-sim-velocity-control-system"
  name="gz::sim::systems::VelocityControl"><initial_linear>0 0 0</initial_linear></plugin>
  <plugin filename="gz-sim-odometry-publisher-system"
  name="gz::sim::systems::OdometryPublisher"><odom_publish_frequency>20</odom_publish_frequency>
  </plugin>
  <plugin filename="gz-sim-pose-publisher-system" name="gz::sim::systems::PosePublisher">
  <publish_model_pose>true</publish_model_pose><use_pose_vector_msg>true</use_pose_vector_msg>
  <update_frequency>10</update_frequency></plugin>"""


def test_velocity_control_drives_the_model_in_its_own_frame_and_odometry_follows():
    world = make_world()
    spawn(world, SYSTEMS)
    world.transport.callbacks["/model/vehicle/cmd_vel"](twist(x=1.0, yaw=math.pi / 4))
    run(world, 2.0)  # a quarter turn along an arc
    body = world.model.body("vehicle/chassis").id
    x, y = world.data.xpos[body][:2]
    radius = 1.0 / (math.pi / 4)
    assert x == pytest.approx(radius * math.sin(math.pi / 2), abs=0.05)
    assert y == pytest.approx(radius * (1 - math.cos(math.pi / 2)), abs=0.05)
    odometry = world.transport.published["/model/vehicle/odometry"][-1]
    assert odometry.header.frame_id == "vehicle/odom"
    assert odometry.child_frame_id == "vehicle/base_footprint"
    assert odometry.pose.position.x == pytest.approx(x, abs=0.01)
    assert odometry.twist.linear.x == pytest.approx(1.0, abs=0.02)  # in the body frame
    assert odometry.twist.angular.z == pytest.approx(math.pi / 4, abs=0.02)
    tf = world.transport.published["/model/vehicle/pose"]
    assert any(getattr(m, "parent", None) == ["vehicle/odom"] for m in tf)


def test_pose_publisher_gives_the_model_and_its_links_relative_to_their_parents():
    world = make_world()
    spawn(world, SYSTEMS)
    run(world, 0.3)
    poses = [m for m in world.transport.published["/model/vehicle/pose"]
             if getattr(m, "parent", None) != ["vehicle/odom"]]
    latest = poses[-1]
    named = dict(zip(latest.name, zip(latest.parent, latest.pose, strict=True), strict=True))
    assert named["vehicle"][0] == world.world_name
    parent, flag = named["flag"]
    assert parent == "vehicle"
    assert (flag.position.x, flag.position.z) == pytest.approx((0.3, 0.3), abs=1e-6)
    assert len(poses) >= 2  # 10 Hz over 0.3 s


def test_bad_velocity_control_values_are_located():
    world = make_world()
    with pytest.raises(SpawnError, match="<string>:9: .*<initial_linear> expects three "
                                         "numbers"):
        spawn(world, '<plugin filename="gz-sim-velocity-control-system" '
                     'name="gz::sim::systems::VelocityControl"><initial_linear>1 two 3'
                     '</initial_linear></plugin>')


@pytest.mark.parametrize("force_mode", [False, True])
def test_joint_controller_holds_a_speed_by_velocity_or_by_a_force_pid(force_mode):
    extra = "<use_force_commands>true</use_force_commands><p_gain>0.2</p_gain>" \
            "<i_gain>2</i_gain><i_max>5</i_max><i_min>-5</i_min><cmd_max>0.1</cmd_max>" \
        if force_mode else ""
    world = make_world()
    spawn(world, f'<plugin filename="gz-sim-joint-controller-system" '
                 f'name="gz::sim::systems::JointController"><joint_name>flag_hinge'
                 f'</joint_name><topic>flag_speed</topic>{extra}</plugin>', z=0.11)
    world.transport.callbacks["/flag_speed"](SimpleNamespace(data=2.0))
    run(world, 0.05)
    early = hinge_speed(world)
    run(world, 3.0)
    assert hinge_speed(world) == pytest.approx(2.0, abs=0.05)
    if force_mode:  # at most 0.1 N·m on the flag (0.01 kg·m²): 10 rad/s²
        assert early < 1.0
    else:  # the speed is held at once, as gz's velocity command holds it
        assert early == pytest.approx(2.0, abs=0.1)


def _link(name: str, pose: str, shape: str = "", mass: float = 1.0) -> str:
    collision = f'<collision name="c"><geometry>{shape}</geometry></collision>' if shape else ""
    return f"""<link name="{name}"><pose>{pose}</pose><inertial><mass>{mass}</mass><inertia>
      <ixx>0.02</ixx><iyy>0.02</iyy><izz>0.02</izz></inertia></inertial>{collision}</link>"""


def _joint(name: str, kind: str, parent: str, child: str, axis: str) -> str:
    return f"""<joint name="{name}" type="{kind}"><parent>{parent}</parent><child>{child}</child>
      <axis><xyz>{axis}</xyz></axis></joint>"""


CAR = """<?xml version="1.0"?><sdf version="1.9"><model name="car">
  {chassis}{parts}
  <plugin filename="gz-sim-ackermann-steering-system" name="gz::sim::systems::AckermannSteering">
    <left_joint>rl</left_joint><right_joint>rr</right_joint>
    <left_steering_joint>fl_steer</left_steering_joint>
    <right_steering_joint>fr_steer</right_steering_joint>
    <kingpin_width>0.9</kingpin_width><steering_limit>0.6</steering_limit>
    <wheel_base>1.2</wheel_base><wheel_separation>1.0</wheel_separation>
    <wheel_radius>0.2</wheel_radius><steer_p_gain>20</steer_p_gain>
  </plugin>
</model></sdf>"""


def car(world, settings: str = "") -> None:
    """The four-wheeled car, steered by AckermannSteering (`settings`: more of its own)."""
    sphere = "<sphere><radius>0.2</radius></sphere>"
    parts = ""
    for side, y in (("l", 0.5), ("r", -0.5)):
        parts += _link(f"f{side}_knuckle", f"0.6 {y} 0.2 0 0 0", mass=0.2)
        parts += _joint(f"f{side}_steer", "revolute", "chassis", f"f{side}_knuckle", "0 0 1")
        parts += _link(f"f{side}_wheel", f"0.6 {y} 0.2 -1.5708 0 0", sphere)
        parts += _joint(f"f{side}", "revolute", f"f{side}_knuckle", f"f{side}_wheel", "0 0 1")
        parts += _link(f"r{side}_wheel", f"-0.6 {y} 0.2 -1.5708 0 0", sphere)
        parts += _joint(f"r{side}", "revolute", "chassis", f"r{side}_wheel", "0 0 1")
    chassis = _link("chassis", "0 0 0.6 0 0 0", "<box><size>1.6 0.6 0.2</size></box>", 5.0)
    text = CAR.format(chassis=chassis, parts=parts).replace("</steer_p_gain>",
                                                            f"</steer_p_gain>{settings}")
    world.spawn(world.templates.from_string(text), "car", [0, 0, 0.02], IDENTITY)


def test_ackermann_steering_drives_and_turns_the_way_it_is_told():
    world = make_world()
    car(world)
    world.transport.callbacks["/model/car/cmd_vel"](twist(x=1.0, yaw=0.4))
    run(world, 3.0)
    body = world.model.body("car/chassis").id
    x, y = world.data.xpos[body][:2]
    assert x > 1.5 and y > 0.2, (x, y)  # forward, curving left
    odometry = world.transport.published["/model/car/odometry"][-1]
    assert odometry.header.frame_id == "car/odom"
    assert odometry.pose.position.x > 1.5 and odometry.pose.position.y > 0.2
    assert odometry.twist.angular.z > 0.1


def test_a_drives_odometry_keeps_its_rate_on_the_grid_when_no_multiple_of_the_step():
    world = make_world()
    car(world, "<odom_publish_frequency>30</odom_publish_frequency>")
    run(world, 3.0)
    assert len(world.transport.published["/model/car/odometry"]) in (90, 91)  # late + 1/30: 89


BATTERY = """<plugin filename="gz-sim-apply-joint-force-system"
  name="gz::sim::systems::ApplyJointForce"><joint_name>flag_hinge</joint_name></plugin>
  <plugin filename="gz-sim-linearbatteryplugin-system"
  name="gz::sim::systems::LinearBatteryPlugin">
  <battery_name>linear_battery</battery_name><voltage>4.2</voltage>
  <open_circuit_voltage_constant_coef>4.2</open_circuit_voltage_constant_coef>
  <open_circuit_voltage_linear_coef>-2.0</open_circuit_voltage_linear_coef>
  <initial_charge>0.001</initial_charge><capacity>0.001</capacity>
  <resistance>0.07</resistance><smooth_current_tau>0.1</smooth_current_tau>
  <power_load>10</power_load><start_on_motion>true</start_on_motion></plugin>"""


def test_a_linear_battery_drains_once_the_model_moves_and_says_when_it_is_empty():
    world = make_world()
    spawn(world, BATTERY)
    topic = "/model/vehicle/battery/linear_battery/state"
    run(world, 0.5)  # not moving: full, not draining
    idle = world.transport.published[topic][-1]
    assert idle.percentage == pytest.approx(1.0) and idle.power_supply_status == 4  # FULL
    world.transport.callbacks["/model/vehicle/joint/flag_hinge/cmd_force"](
        SimpleNamespace(data=0.1))
    run(world, 0.5)
    draining = world.transport.published[topic][-1]
    assert draining.power_supply_status == 2  # DISCHARGING
    assert draining.percentage < 0.9 and draining.current > 1.0  # ~2.4 A at ~4 V
    assert draining.voltage < 4.2
    run(world, 3.0)  # 3.6 A·s of charge at about 2.5 A
    assert any("out of battery" in m for m in world.transport.messages("warning"))
    states = world.transport.published[topic]
    assert all(b.percentage <= a.percentage + 1e-9 for a, b in itertools.pairwise(states))


def test_a_battery_without_capacity_is_refused_at_its_line():
    world = make_world()
    with pytest.raises(SpawnError, match="<string>:11: .*capacity is required"):
        spawn(world, BATTERY.replace("<capacity>0.001</capacity>", ""))
    with pytest.raises(SpawnError, match="<string>:11: .*<capacity> must be greater than 0"):
        spawn(world, BATTERY.replace("<capacity>0.001</capacity>", "<capacity>0</capacity>"))


ARM2 = """<?xml version="1.0"?><sdf version="1.9"><model name="arm"><static>false</static>
  <link name="base"><inertial><mass>50</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz>
  </inertia></inertial></link>
  <joint name="anchor" type="fixed"><parent>world</parent><child>base</child></joint>
  {links}
  <plugin filename="gz-sim-joint-trajectory-controller-system"
    name="gz::sim::systems::JointTrajectoryController">
    <joint_name>j1</joint_name><initial_position>0.3</initial_position>
    <position_p_gain>40</position_p_gain><position_d_gain>4</position_d_gain>
    <position_i_gain>2</position_i_gain><position_i_min>-1</position_i_min>
    <position_i_max>1</position_i_max>
    <joint_name>j2</joint_name><initial_position>-0.2</initial_position>
    <position_p_gain>40</position_p_gain><position_d_gain>4</position_d_gain>
  </plugin>
</model></sdf>"""


def test_gz_joint_trajectory_controller_holds_then_follows_points_and_reports_progress():
    links = ""
    for n, parent in ((1, "base"), (2, "l1")):
        links += f"""<link name="l{n}"><pose>0 0 {0.2 * n} 0 0 0</pose><inertial><mass>1</mass>
          <inertia><ixx>0.02</ixx><iyy>0.02</iyy><izz>0.02</izz></inertia></inertial></link>
          <joint name="j{n}" type="revolute"><parent>{parent}</parent><child>l{n}</child>
          <axis><xyz>0 0 1</xyz></axis></joint>"""
    world = make_world()
    world.spawn(world.templates.from_string(ARM2.format(links=links)), "arm", [0, 0, 0],
                IDENTITY)

    def angle(n: int) -> float:
        return float(world.data.qpos[world.model.joint(f"arm/j{n}").qposadr[0]])

    run(world, 2.0)  # held at the initial positions
    assert (angle(1), angle(2)) == pytest.approx((0.3, -0.2), abs=0.01)
    point = lambda positions, sec: SimpleNamespace(  # noqa: E731
        positions=positions, velocities=[], effort=[],
        time_from_start=SimpleNamespace(sec=sec, nanosec=0))
    stamp = SimpleNamespace(stamp=SimpleNamespace(sec=0, nanosec=0))
    world.transport.callbacks["/model/arm/joint_trajectory"](SimpleNamespace(
        header=stamp, joint_names=["j2", "j1"],
        points=[point([0.5, 1.0], 1), point([0.0, -0.5], 2)]))
    run(world, 1.5)
    assert (angle(1), angle(2)) == pytest.approx((1.0, 0.5), abs=0.02)
    run(world, 1.5)
    assert (angle(1), angle(2)) == pytest.approx((-0.5, 0.0), abs=0.02)
    progress = [m.data for m in world.transport.published["/model/arm/joint_trajectory_progress"]]
    assert progress == [0.5, 1.0]
    world.transport.callbacks["/model/arm/joint_trajectory"](SimpleNamespace(
        header=stamp, joint_names=["elbow"], points=[point([1.0], 1)]))
    run(world, 1.0)
    assert angle(1) == pytest.approx(-0.5, abs=0.02)  # refused: held
    assert any("joint trajectory refused" in m for m in world.transport.messages("warning"))


TRIGGER = """<plugin filename="gz-sim-velocity-control-system"
  name="gz::sim::systems::VelocityControl"/>
  <plugin filename="gz-sim-triggered-publisher-system"
  name="gz::sim::systems::TriggeredPublisher">
  <input type="gz.msgs.Boolean" topic="/start"><match field="data">true</match></input>
  <output type="gz.msgs.Twist" topic="/model/vehicle/cmd_vel">linear: {x: 0.5}</output>
  <output type="gz.msgs.StringMsg" topic="/said">data: "going"</output>
  <delay_ms>500</delay_ms></plugin>"""


def test_triggered_publisher_publishes_its_outputs_when_the_input_matches():
    from launcher.bus.messages import build

    world = make_world()
    spawn(world, TRIGGER)
    body = world.model.body("vehicle/chassis").id
    start = world.transport.callbacks["/start"]
    start(build("mujoco_sim/msg/Boolean", {"data": False}))  # no match
    run(world, 1.0)
    assert "/said" not in world.transport.published or not world.transport.published["/said"]
    x0 = float(world.data.xpos[body][0])
    start(build("mujoco_sim/msg/Boolean", {"data": True}))
    run(world, 0.3)  # within the delay: nothing yet
    assert not world.transport.published.get("/said")
    run(world, 1.0)
    assert [m.data for m in world.transport.published["/said"]] == ["going"]
    # the Twist output went to the model's VelocityControl (on the stand-in bus, by hand)
    twist = world.transport.published["/model/vehicle/cmd_vel"][-1]
    world.transport.callbacks["/model/vehicle/cmd_vel"](twist)
    run(world, 1.0)
    assert float(world.data.xpos[body][0]) > x0 + 0.4


@pytest.mark.parametrize("change, expected", [
    ('type="gz.msgs.Boolean"', r"no message type 'gz.msgs.Bolean' \(did you mean 'gz.msgs.Boolean'"),
    ("linear: {x: 0.5}", "does not fit"),
    ("<delay_ms>500</delay_ms>", None),
])
def test_triggered_publisher_mistakes_are_located(change, expected):
    world = make_world()
    text = TRIGGER
    if change.startswith("type="):
        text = text.replace(change, 'type="gz.msgs.Bolean"')
    elif change.startswith("linear"):
        text = text.replace(change, "linear: {q: 1}")
    else:
        text = text.replace('<input type="gz.msgs.Boolean" topic="/start">', "<nothing>") \
            .replace("</input>", "</nothing>")
        expected = "needs <input"
    with pytest.raises(SpawnError, match=rf"<string>:\d+: .*{expected}"):
        spawn(world, text)


def test_an_unknown_type_of_a_package_is_matched_against_all_its_types_read_or_not():
    """(In a fresh interpreter: a suggestion must not depend on the types read before.)"""
    import subprocess
    import sys

    said = subprocess.run([sys.executable, "-c", (
        "from launcher.bus.types import registry\n"
        "try:\n    registry().message_class('mujoco_sim/msg/Bolean')\n"
        "except Exception as exc:\n    print(exc)")], capture_output=True, text=True,
        timeout=60).stdout
    assert "did you mean 'mujoco_sim/msg/Boolean'" in said, said
