"""rclpy.publisher.Publisher over launcher's bus publisher."""

from __future__ import annotations

from typing import Any

from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.duration import Duration  # noqa: F401
from rclpy.event_handler import EventHandler, PublisherEventCallbacks  # noqa: F401
from rclpy.properties import readonly
from rclpy.qos import QoSProfile  # noqa: F401


class Publisher:
    def __init__(self, publisher_impl: Any, msg_type: Any, topic: str, qos_profile: Any,
                 event_callbacks: Any = None, callback_group: Any = None) -> None:
        """`publisher_impl`: launcher's bus publisher (Node.create_publisher makes both)."""
        self._bus, self.msg_type, self._qos_profile = publisher_impl, msg_type, qos_profile
        self.event_callbacks, self.callback_group = event_callbacks, callback_group
        self._serialize = publisher_impl.publish

    topic_name = readonly("_bus.topic", "The topic's fully qualified name (`topic` too).")
    topic = topic_name
    qos_profile = readonly("_qos_profile", "The publisher's QoSProfile.")
    handle = readonly("_bus", "The launcher bus publisher under this one.")

    def publish(self, msg: Any) -> None:
        """Publish a message of the publisher's type (or its serialized bytes)."""
        if isinstance(msg, bytes | bytearray | memoryview):  # serialised already
            self._bus.publish_raw(bytes(msg))
            return
        if type(msg) is not self.msg_type:
            raise TypeError(f"Expected {self.msg_type}, got {type(msg)}")
        self._serialize(msg)

    def get_subscription_count(self) -> int:
        """How many subscriptions on the graph match the publisher."""
        return self._bus.get_subscription_count()

    def assert_liveliness(self) -> None:
        """Nothing to do: launcher's graph keeps liveliness itself."""
        pass

    def wait_for_all_acked(self, timeout: Any = None) -> bool:
        """True: launcher's reliable delivery needs no acknowledgement wait."""
        return True

    def destroy(self) -> None:
        """Take the publisher off the graph."""
        self._bus.destroy()
