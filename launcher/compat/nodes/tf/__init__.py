"""ROS 1's tf for rospy, over the tf2 tree: TransformListener (lookupTransform,
waitForTransform, canTransform, getLatestCommonTime, frameExists, getFrameStrings),
TransformBroadcaster (sendTransform(translation, rotation, time, child, parent)), tf's
exceptions, and tf.transformations' Euler and quaternion helpers."""

from __future__ import annotations

import time as _time
from typing import Any

from tf2_ros import Buffer
from tf2_ros import TransformListener as _Listener
from tf2_ros.buffer_core import (
    ConnectivityException,
    ExtrapolationException,
    LookupException,
    TransformException,
)

from tf import transformations  # noqa: F401  (tf.transformations, as ROS 1 code uses it)

Exception = TransformException  # noqa: A001  (tf.Exception, ROS 1's name)
__all__ = ["ConnectivityException", "Exception", "ExtrapolationException", "LookupException",
           "TransformBroadcaster", "TransformListener", "transformations"]


def _ns(stamp: Any) -> int:
    if stamp is None:
        return 0
    if hasattr(stamp, "to_nsec"):
        return int(stamp.to_nsec())
    return int(float(stamp) * 1e9)


class TransformListener:
    def __init__(self, interpolate: bool = True, cache_time: Any = None) -> None:
        self._buffer = Buffer()
        self._listener = _Listener(self._buffer)

    def lookupTransform(self, target_frame: str, source_frame: str,  # noqa: N802
                        time: Any) -> tuple[list[float], list[float]]:
        """([x, y, z], [qx, qy, qz, qw]) of source_frame in target_frame."""
        pose, _ = self._buffer.core.lookup(target_frame, source_frame, _ns(time))
        return list(pose[0]), list(pose[1])

    def canTransform(self, target_frame: str, source_frame: str,  # noqa: N802
                     time: Any) -> bool:
        """Whether the transform from `source_frame` to `target_frame` at
        `time` can be looked up now.
        """
        return self._buffer.core.can_transform(target_frame, source_frame, _ns(time))[0]

    def waitForTransform(self, target_frame: str, source_frame: str, time: Any,  # noqa: N802
                         timeout: Any, polling_sleep_duration: Any = None) -> None:
        """Wait until it can be looked up; tf.Exception after
        `timeout`.
        """
        seconds = timeout.to_sec() if hasattr(timeout, "to_sec") else float(timeout)
        deadline = _time.monotonic() + seconds
        while True:
            ok, why = self._buffer.core.can_transform(target_frame, source_frame, _ns(time))
            if ok:
                return
            if _time.monotonic() > deadline:
                raise TransformException(f"{why} (after waiting {seconds:g} s)")
            _time.sleep(0.01)

    def getLatestCommonTime(self, source_frame: str, target_frame: str) -> Any:  # noqa: N802
        """The latest time both frames' chains have data for."""
        import rospy

        stamp = self._buffer.core.common_time(target_frame, source_frame)
        return rospy.Time(stamp // 1_000_000_000, stamp % 1_000_000_000)

    def frameExists(self, frame_id: str) -> bool:  # noqa: N802
        """Whether the tree knows `frame_id`."""
        return frame_id.lstrip("/") in self._buffer.core.frames()

    def getFrameStrings(self) -> list[str]:  # noqa: N802
        """Every frame the tree knows."""
        return self._buffer.core.frames()


class TransformBroadcaster:
    def __init__(self, queue_size: int = 100) -> None:
        import rospy
        from tf2_msgs.msg import TFMessage

        self._message = TFMessage
        self.pub_tf = rospy.Publisher("/tf", TFMessage, queue_size=queue_size)

    def sendTransform(self, translation: Any, rotation: Any, time: Any, child: str,  # noqa: N802
                      parent: str) -> None:
        """Publish one transform from a translation and a quaternion."""
        from geometry_msgs.msg import TransformStamped

        t = TransformStamped()
        stamp = _ns(time)
        t.header.stamp.sec, t.header.stamp.nanosec = divmod(stamp, 1_000_000_000)
        t.header.frame_id, t.child_frame_id = parent, child
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = \
            (float(v) for v in translation)
        (t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
         t.transform.rotation.w) = (float(v) for v in rotation)
        self.pub_tf.publish(self._message(transforms=[t]))

    def sendTransformMessage(self, transform: Any) -> None:  # noqa: N802
        """Publish one TransformStamped."""
        self.pub_tf.publish(self._message(transforms=[transform]))
