"""tf2_ros.StaticTransformBroadcaster: static transforms on `/tf_static`, latched; each send
publishes all it has sent so far (a newer one for a child frame replaces the older), so a
late listener gets the whole set, as tf2_ros does."""

from __future__ import annotations

from typing import Any


class StaticTransformBroadcaster:
    def __init__(self, node: Any = None, qos: Any = None) -> None:
        from tf2_msgs.msg import TFMessage

        self._message = TFMessage
        if node is None:  # ROS 1's: StaticTransformBroadcaster(), latched on rospy's node
            import rospy

            self.pub_tf = rospy.Publisher("/tf_static", TFMessage, latch=True, queue_size=100)
        else:
            from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile

            qos = qos or QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                                    history=HistoryPolicy.KEEP_LAST)
            self.pub_tf = node.create_publisher(TFMessage, "/tf_static", qos)
        self.net_message = TFMessage()
        self._child_frames: dict[str, Any] = {}

    def sendTransform(self, transform: Any) -> None:  # noqa: N802 (tf2_ros's name)
        """Publish transforms on /tf_static (latched), with those sent before: each
        child frame keeps its latest.
        """
        for one in list(transform) if isinstance(transform, list | tuple) else [transform]:
            self._child_frames[one.child_frame_id] = one
        self.net_message = self._message(transforms=list(self._child_frames.values()))
        self.pub_tf.publish(self.net_message)
