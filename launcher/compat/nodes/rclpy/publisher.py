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
        return self._bus.topic

    @property
    def topic(self) -> str:
        return self._bus.topic

    @property
    def qos_profile(self) -> Any:
        return self._qos_profile

    def publish(self, msg: Any) -> None:
        if isinstance(msg, bytes | bytearray | memoryview):  # serialised already
            self._bus.publish_raw(bytes(msg))
            return
        if type(msg) is not self.msg_type:
            raise TypeError(f"Expected {self.msg_type}, got {type(msg)}")
        self._serialize(msg)

    def get_subscription_count(self) -> int:
        return self._bus.get_subscription_count()

    def assert_liveliness(self) -> None:
        pass

    def wait_for_all_acked(self, timeout: Any = None) -> bool:
        return True

    def destroy(self) -> None:
        self._bus.destroy()

    @property
    def handle(self) -> Any:
        return self._bus
