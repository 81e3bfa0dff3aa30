"""tf2_ros.TransformBroadcaster: TransformStamped (one or a list) on `/tf`."""

from __future__ import annotations

from typing import Any


class TransformBroadcaster:
    def __init__(self, node: Any = None, qos: Any = None, **ros1: Any) -> None:
        from tf2_msgs.msg import TFMessage

        self._message = TFMessage
        if node is None:  # ROS 1's: TransformBroadcaster(), on rospy's node
            import rospy

            self.pub_tf = rospy.Publisher("/tf", TFMessage, queue_size=100)
            return
        self.pub_tf = node.create_publisher(TFMessage, "/tf", qos or 100)

    def sendTransform(self, transform: Any) -> None:  # noqa: N802 (tf2_ros's name)
        """Publish one TransformStamped, or a list of them, on /tf."""
        transforms = list(transform) if isinstance(transform, list | tuple) else [transform]
        self.pub_tf.publish(self._message(transforms=transforms))
