"""Gazebo's motion and pose systems on the sim (a stand-in bus that records): ApplyJointForce,
VelocityControl, OdometryPublisher and PosePublisher, as gz-sim documents them."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from launcher.sim.entity import SpawnError
from tests.unit.test_sim import IDENTITY, make_world

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
