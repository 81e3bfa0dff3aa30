"""launcher's rosbag shim: bags it writes read back through it and through rosbags' own reader
(an independent one, with ROS 1's Noetic definitions), with topic and time filters, type and
topic info, appending, and rosbag's errors."""

from __future__ import annotations

import pytest
from rosbags.rosbag1 import Reader
from rosbags.typesys import Stores, get_typestore

from launcher import compat
from launcher.compat import rosidl

rosbag = rospy = PoseStamped = String = None  # (imported by the fixture below)


@pytest.fixture(scope="module", autouse=True)
def ros1_modules():
    """rosbag, rospy and the messages, imported for this module's tests only: importing rospy
    makes this process's message fields take ints for floats (ROS 1's leniency), which the
    other tests of the process must not inherit."""
    global rosbag, rospy, PoseStamped, String
    strict = rosidl._lenient
    compat.enable_in_process()
    import rosbag
    import rospy
    from geometry_msgs.msg import PoseStamped
    from std_msgs.msg import String
    yield
    rosidl._lenient = strict


def pose(n: int):
    message = PoseStamped()
    message.header.seq, message.header.frame_id = n, "map"
    message.header.stamp = rospy.Time(100 + n, 5)
    message.pose.position.x = float(n)
    return message


@pytest.fixture
def bag_path(tmp_path):
    path = tmp_path / "test.bag"
    with rosbag.Bag(str(path), "w") as bag:
        for n in range(4):
            bag.write("/chatter", String(data=f"hello {n}"), rospy.Time(10 + n, 0))
            bag.write("/pose", pose(n), rospy.Time(10 + n, 500))
    return path


def test_written_bag_reads_back_through_the_shim(bag_path):
    with rosbag.Bag(str(bag_path)) as bag:
        read = list(bag.read_messages())
    assert [m.topic for m in read] == ["/chatter", "/pose"] * 4
    assert [m.message.data for m in read if m.topic == "/chatter"] == \
        [f"hello {n}" for n in range(4)]
    poses = [m.message for m in read if m.topic == "/pose"]
    assert [(p.header.seq, p.header.frame_id, p.pose.position.x) for p in poses] == \
        [(n, "map", float(n)) for n in range(4)]
    assert poses[0] == pose(0)
    assert isinstance(read[0].timestamp, rospy.Time)
    assert read[1].timestamp == rospy.Time(10, 500)


def test_written_bag_reads_back_through_rosbags_with_ros1_definitions(bag_path):
    store = get_typestore(Stores.ROS1_NOETIC)
    with Reader(bag_path) as reader:
        digests = {c.topic: (c.msgtype, c.digest) for c in reader.connections}
        read = [(c.topic, t, store.deserialize_ros1(data, c.msgtype))
                for c, t, data in reader.messages()]
    assert digests == {
        "/chatter": ("std_msgs/msg/String", store.generate_msgdef("std_msgs/msg/String")[1]),
        "/pose": ("geometry_msgs/msg/PoseStamped",
                  store.generate_msgdef("geometry_msgs/msg/PoseStamped")[1])}
    assert [(topic, t) for topic, t, _ in read][:2] == [("/chatter", 10_000_000_000),
                                                        ("/pose", 10_000_000_500)]
    header = read[3][2].header
    assert (header.seq, header.frame_id, header.stamp.sec, header.stamp.nanosec) == \
        (1, "map", 101, 5)
    assert read[2][2].data == "hello 1"


def test_read_messages_filters_topics_and_times_inclusively(bag_path):
    with rosbag.Bag(str(bag_path)) as bag:
        chosen = list(bag.read_messages(topics="/pose", start_time=rospy.Time(11, 500),
                                        end_time=rospy.Time(12, 500)))
        assert [m.message.header.seq for m in chosen] == [1, 2]
        assert list(bag.read_messages(topics=["/nothing"])) == []
        only = bag.read_messages(connection_filter=lambda topic, *_: topic == "/chatter")
        assert {m.topic for m in only} == {"/chatter"}


def test_type_and_topic_info_counts_and_times(bag_path):
    with rosbag.Bag(str(bag_path)) as bag:
        info = bag.get_type_and_topic_info()
        assert set(info.msg_types) == {"std_msgs/String", "geometry_msgs/PoseStamped"}
        chatter = info.topics["/chatter"]
        assert (chatter.msg_type, chatter.message_count, chatter.connections) == \
            ("std_msgs/String", 4, 1)
        assert chatter.frequency == pytest.approx(1.0)
        assert bag.get_message_count() == 8
        assert bag.get_message_count("/pose") == 4
        assert bag.get_start_time() == 10.0
        assert bag.get_end_time() == pytest.approx(13.0000005)


def test_a_bag_being_written_reads_what_it_holds_and_appends(bag_path):
    with rosbag.Bag(str(bag_path), "a", compression=rosbag.Compression.BZ2) as bag:
        bag.write("/chatter", String(data="later"), rospy.Time(20))
        assert bag.get_message_count("/chatter") == 5
        assert [m.message.data for m in bag.read_messages("/chatter")][-1] == "later"
    with rosbag.Bag(str(bag_path)) as bag:
        assert bag.get_message_count() == 9


def test_bad_mode_and_closed_bag_are_value_errors(bag_path):
    with pytest.raises(ValueError, match='mode "x" is invalid'):
        rosbag.Bag(str(bag_path), "x")
    with pytest.raises(ValueError, match="compression"):
        rosbag.Bag(str(bag_path), "w", compression="zip")
    bag = rosbag.Bag(str(bag_path))
    bag.close()
    with pytest.raises(ValueError, match="closed"):
        bag.get_message_count()


def test_not_a_bag_is_a_rosbag_exception(tmp_path):
    path = tmp_path / "not.bag"
    path.write_text("hello")
    with pytest.raises(rosbag.ROSBagException):
        rosbag.Bag(str(path))
