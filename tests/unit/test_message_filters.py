"""message_filters, as ROS 2's: synchronizers pair messages by stamp (exactly, or within a
slop), a Cache keeps the latest by stamp. Fed by hand: the filters are plain Python."""

from __future__ import annotations

from launcher.compat import finder

finder.install()

import message_filters  # noqa: E402
from rclpy.time import Time  # noqa: E402
from sensor_msgs.msg import CameraInfo, Image  # noqa: E402
from std_msgs.msg import String  # noqa: E402


def stamped(cls, sec: float):
    message = cls()
    message.header.stamp = Time(nanoseconds=int(sec * 1e9)).to_msg()
    return message


def test_time_synchronizer_pairs_equal_stamps_only():
    images, infos = message_filters.SimpleFilter(), message_filters.SimpleFilter()
    pairs = []
    sync = message_filters.TimeSynchronizer([images, infos], 10)
    sync.registerCallback(lambda i, c: pairs.append((i.header.stamp.sec, c.header.stamp.sec)))
    images.signalMessage(stamped(Image, 1))
    infos.signalMessage(stamped(CameraInfo, 2))
    assert pairs == []
    infos.signalMessage(stamped(CameraInfo, 1))
    images.signalMessage(stamped(Image, 2))
    assert pairs == [(1, 1), (2, 2)]


def test_approximate_synchronizer_pairs_within_the_slop():
    images, infos = message_filters.SimpleFilter(), message_filters.SimpleFilter()
    pairs = []
    sync = message_filters.ApproximateTimeSynchronizer([images, infos], 10, slop=0.05)
    sync.registerCallback(lambda i, c: pairs.append(
        (round(Time.from_msg(i.header.stamp).nanoseconds / 1e9, 2),
         round(Time.from_msg(c.header.stamp).nanoseconds / 1e9, 2))))
    images.signalMessage(stamped(Image, 1.00))
    infos.signalMessage(stamped(CameraInfo, 1.20))  # too far
    assert pairs == []
    infos.signalMessage(stamped(CameraInfo, 1.03))
    assert pairs == [(1.0, 1.03)]
    headerless = message_filters.ApproximateTimeSynchronizer(
        [message_filters.SimpleFilter(), message_filters.SimpleFilter()], 5, 0.1,
        allow_headerless=True)
    headerless.add(String(data="x"), headerless.queues[0])  # stamped on arrival: no error


def test_cache_keeps_the_latest_by_stamp():
    source = message_filters.SimpleFilter()
    cache = message_filters.Cache(source, cache_size=3)
    for sec in (1, 3, 2, 4):
        source.signalMessage(stamped(Image, sec))
    assert [m.header.stamp.sec for m in cache.getInterval(Time(seconds=0), Time(seconds=9))] \
        == [2, 3, 4]
    assert cache.getLast().header.stamp.sec == 4
    assert cache.getElemAfterTime(Time(seconds=2.5)).header.stamp.sec == 3
    assert cache.getElemBeforeTime(Time(seconds=2.5)).header.stamp.sec == 2
    assert cache.getOldestTime().nanoseconds == 2_000_000_000
