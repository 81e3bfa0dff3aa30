"""robot_state_publisher's kinematics and /tf packing, against hand-computed transforms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from launcher.bus.types import registry
from launcher.errors import LaunchError
from launcher.nodes.kinematics import Tree
from tests.support.robots import CHAIN, SDF_ROBOT


def rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_y(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rot_z(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def homogeneous(rotation, translation):
    matrix = np.eye(4)
    matrix[:3, :3], matrix[:3, 3] = rotation, translation
    return matrix


def from_quaternion(q):
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def test_forward_kinematics_matches_a_hand_computed_chain():
    tree = Tree.parse(CHAIN)
    q1, q2, q3 = 0.3, -1.1, 0.25
    positions = np.zeros(len(tree.moving))
    positions[[tree.index["j1"], tree.index["j2"], tree.index["j3"]]] = q1, q2, q3
    translation, quat = tree.transforms(positions)
    chain = np.eye(4)
    for name in ("j1", "j2", "j3"):
        i = tree.index[name]
        chain = chain @ homogeneous(from_quaternion(quat[i]), translation[i])
    expected = (homogeneous(rot_z(q1), [0, 0, 1])
                @ homogeneous(rot_z(math.pi / 2) @ rot_y(q2), [0.5, 0, 0])
                @ homogeneous(rot_x(math.pi / 4), [0.2, 0.1, 0])
                @ homogeneous(np.eye(3), [q3, 0, 0]))
    assert np.abs(chain - expected).max() < 1e-9
    assert np.linalg.norm(quat, axis=1) == pytest.approx(1.0, abs=1e-12)


def test_fixed_joints_are_static_and_mimic_joints_are_known():
    tree = Tree.parse(CHAIN)
    assert [j.name for j in tree.fixed] == ["tool_mount"]
    assert tree.root == "base"
    fb = next(j for j in tree.moving if j.name == "fb")
    assert fb.mimic == ("fa", -1.0, 0.01)


@pytest.mark.parametrize("text, expected", [
    ("", "robot_description is empty"),
    ("<robot name='r'><link name='a'>", "robot_description:1:"),
    ("<robot name='r'><link name='a'/><link name='b'/></robot>", "2 root links (a, b)"),
    ("<robot name='r'><link name='a'/><link name='b'/><link name='c'/>"
     "<joint name='j1' type='fixed'><parent link='a'/><child link='c'/></joint>"
     "<joint name='j2' type='fixed'><parent link='b'/><child link='c'/></joint></robot>",
     "link 'c' has two parent joints ('j1' and 'j2')"),
    ("<robot name='r'><link name='a'/><link name='b'/>"
     "<joint name='j1' type='fixed'><parent link='b'/><child link='a'/></joint>"
     "<joint name='j2' type='fixed'><parent link='a'/><child link='b'/></joint></robot>",
     "no root link: the joints form a loop"),
    ("<robot name='r'><link name='a'/><link name='b'/><joint name='j' type='hinge'>"
     "<parent link='a'/><child link='b'/></joint></robot>", "type 'hinge'"),
])
def test_bad_urdfs_are_clear_errors(text, expected):
    with pytest.raises(LaunchError) as error:
        Tree.parse(text)
    assert expected in str(error.value)


class Recorded:
    def __init__(self):
        self.payloads, self.warnings = [], []

    def publish_raw(self, payload):
        self.payloads.append(payload)

    def warning(self, message, once=False):
        self.warnings.append(message)


def test_the_rate_limiter_and_time_going_backwards():
    import threading

    from launcher.nodes.robot_state_publisher import RobotStatePublisher

    publisher = RobotStatePublisher.__new__(RobotStatePublisher)  # no node: on_joints alone
    recorded = Recorded()
    publisher.tree, publisher.prefix, publisher.ignore_timestamp = Tree.parse(CHAIN), "", False
    publisher.frequency, publisher.log, publisher.tf_pub = 20.0, recorded, recorded
    publisher._mimics, publisher._plans, publisher._warned = [], {}, set()
    publisher._last_stamp, publisher._lock = None, threading.Lock()
    for ms in (0, 10, 49, 50, 120, 30):  # 20 Hz: 0, 50 and 120 pass; 30 is a reset
        publisher.on_joints(1, ms * 1_000_000, ["j1"], np.array([0.1]))
    stamps = [registry().deserialize(p, "tf2_msgs/msg/TFMessage").transforms[0].header.stamp
              for p in recorded.payloads]
    assert [s.nanosec // 1_000_000 for s in stamps] == [0, 50, 120, 30]
    publisher.ignore_timestamp = True
    publisher.on_joints(1, 31_000_000, ["j1"], np.array([0.2]))
    assert len(recorded.payloads) == 5




def test_an_sdf_robot_description_is_read_as_sdformat_urdf_reads_it():
    tree = Tree.parse(SDF_ROBOT)
    assert (tree.name, tree.root) == ("pendulum", "base")
    assert [(j.name, j.kind, j.parent, j.child) for j in tree.moving] == [
        ("hinge", "revolute", "base", "arm"), ("spin", "continuous", "arm", "tip")]
    hinge = tree.moving[0]
    assert hinge.xyz == pytest.approx((0.0, 0.2, 0.0))  # the child's pose in the parent's
    assert hinge.quat == pytest.approx((0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4)))
    # SDF 1.9 gives the axis in the joint's frame (the child's, here): URDF's too
    assert hinge.axis == pytest.approx((1.0, 0.0, 0.0), abs=1e-6)
    spin = tree.moving[1]
    assert spin.xyz == pytest.approx((0.0, 0.0, -0.5), abs=1e-6)
    translations, quats = tree.transforms([0.0, 0.0])
    assert translations[0] == pytest.approx((0.0, 0.2, 0.0))


def test_an_sdf_joint_robot_state_publisher_cannot_follow_is_named():
    with pytest.raises(LaunchError, match="joint 'hinge' is a screw joint"):
        Tree.parse(SDF_ROBOT.replace('name="hinge" type="revolute"', 'name="hinge" type="screw"'))


@pytest.mark.parametrize("kind", ["ball", "universal"])
def test_an_sdf_ball_or_universal_joint_is_floating_as_sdformat_urdf_makes_it(kind):
    """sdformat_urdf (since 1.0.0) converts them into floating joints: the description is
    taken, the joint neither moves nor is fixed, the others are followed."""
    tree = Tree.parse(SDF_ROBOT.replace('name="hinge" type="revolute"',
                                        f'name="hinge" type="{kind}"'))
    assert [j.name for j in tree.moving] == ["spin"]
    assert [(j.name, j.kind) for j in tree.joints if j.name == "hinge"] == [("hinge", "floating")]
