"""tf2_ros's buffer, without a bus: lookups through chains at times, interpolation, the latest
common time, tf2's exceptions with their useful texts, a frame given two parents, waiting for
data with a timeout, tf2_geometry_msgs' transforms."""

from __future__ import annotations

import math
import threading
import time

import pytest

from launcher.compat import finder

finder.install()

import tf2_geometry_msgs  # noqa: E402
import tf2_ros  # noqa: E402
from geometry_msgs.msg import PointStamped, PoseStamped, TransformStamped  # noqa: E402
from rclpy.duration import Duration  # noqa: E402
from rclpy.time import Time  # noqa: E402


def transform(parent: str, child: str, x: float = 0.0, yaw: float = 0.0, sec: int = 1,
              y: float = 0.0) -> TransformStamped:
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = parent, child
    t.header.stamp.sec = sec
    t.transform.translation.x, t.transform.translation.y = x, y
    t.transform.rotation.z, t.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return t


@pytest.fixture
def tree() -> tf2_ros.Buffer:
    """map -static-> odom -(1 s, 3 s)-> base -static-> laser."""
    buffer = tf2_ros.Buffer()
    buffer.set_transform_static(transform("map", "odom", 1.0), "test")
    buffer.set_transform(transform("odom", "base", 2.0, math.pi / 2, sec=1), "test")
    buffer.set_transform(transform("odom", "base", 4.0, math.pi / 2, sec=3), "test")
    buffer.set_transform_static(transform("base", "laser", 0.5), "test")
    return buffer


def xyz(t: TransformStamped) -> tuple[float, float, float]:
    v = t.transform.translation
    return v.x, v.y, v.z


def test_a_lookup_composes_the_chain_at_the_latest_common_time_or_the_time_asked(tree):
    latest = tree.lookup_transform("map", "laser", Time())
    assert (latest.header.stamp.sec, latest.header.frame_id, latest.child_frame_id) == \
        (3, "map", "laser")
    assert xyz(latest) == pytest.approx((5.0, 0.5, 0.0))  # the laser turned with the base
    halfway = tree.lookup_transform("map", "laser", Time(seconds=2))
    assert xyz(halfway) == pytest.approx((4.0, 0.5, 0.0))  # interpolated
    back = tree.lookup_transform("laser", "map", Time(seconds=2))
    assert xyz(back) == pytest.approx((-0.5, 4.0, 0.0))  # the inverse
    assert tree.can_transform("odom", "laser", Time(seconds=1))
    assert not tree.can_transform("odom", "laser", Time(seconds=9))
    full = tree.lookup_transform_full("laser", Time(seconds=1), "laser", Time(seconds=3), "odom")
    assert xyz(full) == pytest.approx((0.0, -2.0, 0.0))  # where the laser went, seen from before


def test_rotation_is_interpolated_on_the_short_way_round():
    buffer = tf2_ros.Buffer()
    buffer.set_transform(transform("a", "b", yaw=math.radians(170), sec=1), "t")
    buffer.set_transform(transform("a", "b", yaw=math.radians(-170), sec=2), "t")
    q = buffer.lookup_transform("a", "b", Time(seconds=1.5)).transform.rotation
    assert abs(2 * math.atan2(q.z, q.w)) == pytest.approx(math.pi, abs=1e-6)  # via 180°


def test_tf2s_exceptions_say_what_frames_there_are_and_what_times(tree):
    with pytest.raises(tf2_ros.LookupException, match=r'"nowhere" passed to lookupTransform '
                       r"argument source_frame does not exist\. Known frames: base, laser, "
                       r"map, odom"):
        tree.lookup_transform("map", "nowhere", Time())
    with pytest.raises(tf2_ros.ExtrapolationException,
                       match=r"extrapolation into the future\.  Requested time 5\.000000 but "
                             r"the latest data is at time 3\.000000, when looking up transform"
                             r" from frame \[laser\] to frame \[map\]"):
        tree.lookup_transform("map", "laser", Time(seconds=5))
    with pytest.raises(tf2_ros.ExtrapolationException, match="into the past"):
        tree.lookup_transform("map", "laser", Time(nanoseconds=500_000_000))
    tree.set_transform_static(transform("world", "other", 1.0), "test")
    with pytest.raises(tf2_ros.ConnectivityException, match="not part of the same tree"):
        tree.lookup_transform("map", "other", Time())
    assert not tree.set_transform(transform("a", "a"), "test")  # TF_SELF_TRANSFORM: refused


def test_a_frame_given_two_parents_is_said_once_and_the_newest_parent_wins():
    said: list[str] = []
    buffer = tf2_ros.Buffer()
    buffer.core.warn = said.append
    buffer.set_transform(transform("base", "wheel", 1.0, sec=1), "urdf")
    buffer.set_transform(transform("chassis", "wheel", 2.0, sec=2), "other_node")
    buffer.set_transform(transform("chassis", "wheel", 2.0, sec=3), "other_node")
    assert len(said) == 1 and "frame 'wheel' has two parents: 'base' (from \"urdf\") and now " \
        "'chassis' (from \"other_node\")" in said[0]
    assert buffer.lookup_transform("chassis", "wheel", Time()).header.stamp.sec == 3


def test_a_timeout_waits_for_the_transform_to_come():
    buffer = tf2_ros.Buffer()
    buffer.set_transform(transform("map", "base", 1.0, sec=1), "t")
    threading.Timer(0.2, lambda: buffer.set_transform(transform("map", "base", 2.0, sec=2),
                                                      "t")).start()
    start = time.monotonic()
    late = buffer.lookup_transform("map", "base", Time(seconds=2), Duration(seconds=5))
    assert xyz(late) == pytest.approx((2.0, 0.0, 0.0))
    assert time.monotonic() - start < 4
    with pytest.raises(tf2_ros.TimeoutException, match="after waiting 0.1 s"):
        buffer.lookup_transform("map", "base", Time(seconds=9), Duration(seconds=0.1))


def test_tf2_geometry_msgs_transforms_points_and_poses(tree):
    point = PointStamped()
    point.header.frame_id, point.header.stamp.sec, point.point.x = "laser", 2, 1.0
    moved = tree.transform(point, "map")
    assert (moved.header.frame_id, moved.point.x, moved.point.y) == \
        ("map", pytest.approx(4.0), pytest.approx(1.5))
    pose = PoseStamped()
    pose.header.frame_id, pose.header.stamp.sec, pose.pose.orientation.w = "base", 3, 1.0
    seen = tree.transform(pose, "odom")
    assert seen.pose.position.x == pytest.approx(4.0)
    assert 2 * math.atan2(seen.pose.orientation.z, seen.pose.orientation.w) == \
        pytest.approx(math.pi / 2)
    t = tree.lookup_transform("map", "base", Time(seconds=3))
    assert tf2_geometry_msgs.do_transform_pose(pose.pose, t).position.x == pytest.approx(5.0)
