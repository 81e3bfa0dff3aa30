"""rclpy.publisher.Publisher over launcher's bus publisher."""

from __future__ import annotations

from typing import Any


class Publisher:
    def __init__(self, bus: Any, msg_type: Any, topic: str, qos_profile: Any,
                 event_callbacks: Any = None) -> None:
        self._bus, self.msg_type, self._qos_profile = bus, msg_type, qos_profile
        self.event_callbacks = event_callbacks
        self._serialize = bus.publish

    @property
    def topic_name(self) -> str:
        """The topic's fully qualified name."""
        return self._bus.topic

    @property
    def topic(self) -> str:
        """The topic's fully qualified name."""
        return self._bus.topic

    @property
    def qos_profile(self) -> Any:
        """The publisher's QoSProfile."""
        return self._qos_profile

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

    @property
    def handle(self) -> Any:
        """The launcher bus publisher under this one."""
        return self._bus
