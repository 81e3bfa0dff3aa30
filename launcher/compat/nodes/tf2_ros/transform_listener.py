"""tf2_ros.TransformListener: fills a Buffer from `/tf` (volatile, depth 100) and `/tf_static`
(transient local, so a late listener gets the static transforms already sent), as tf2_ros."""

from __future__ import annotations

import threading
from typing import Any


class TransformListener:
    def __init__(self, buffer: Any, node: Any = None, *, spin_thread: bool = False,
                 qos: Any = None, static_qos: Any = None, **ros1: Any) -> None:
        from tf2_msgs.msg import TFMessage

        self.buffer, self.node = buffer, node
        if node is None:  # ROS 1's tf2_ros: TransformListener(buffer), on rospy's node
            import rospy

            self.tf_sub = rospy.Subscriber("/tf", TFMessage, self.callback, queue_size=100)
            self.tf_static_sub = rospy.Subscriber("/tf_static", TFMessage,
                                                  self.static_callback, queue_size=100)
            return
        from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile

        if buffer.core.warn is None:
            buffer.core.warn = node.get_logger().warning
        qos = qos or QoSProfile(depth=100, durability=DurabilityPolicy.VOLATILE,
                                history=HistoryPolicy.KEEP_LAST)
        static_qos = static_qos or QoSProfile(depth=100,
                                              durability=DurabilityPolicy.TRANSIENT_LOCAL,
                                              history=HistoryPolicy.KEEP_LAST)
        self.tf_sub = node.create_subscription(TFMessage, "/tf", self.callback, qos)
        self.tf_static_sub = node.create_subscription(TFMessage, "/tf_static",
                                                      self.static_callback, static_qos)
        self._thread = None
        if spin_thread:
            from rclpy.executors import SingleThreadedExecutor

            self._executor = SingleThreadedExecutor()
            self._executor.add_node(node)
            self._thread = threading.Thread(target=self._executor.spin, daemon=True)
            self._thread.start()

    def _authority(self, message: Any) -> str:
        return self.node.get_fully_qualified_name()

    def callback(self, message: Any) -> None:
        """Take the transforms of a /tf message into the buffer."""
        for transform in message.transforms:
            self.buffer.set_transform(transform, "default_authority")

    def static_callback(self, message: Any) -> None:
        """Take the transforms of a /tf_static message into the buffer."""
        for transform in message.transforms:
            self.buffer.set_transform_static(transform, "default_authority")

    def unregister(self) -> None:
        """Stop listening: its /tf and /tf_static subscriptions leave the graph."""
        if self.node is None:
            self.tf_sub.unregister()
            self.tf_static_sub.unregister()
            return
        self.node.destroy_subscription(self.tf_sub)
        self.node.destroy_subscription(self.tf_static_sub)

    def __del__(self) -> None:
        pass
