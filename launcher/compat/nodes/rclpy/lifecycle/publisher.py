"""rclpy.lifecycle.LifecyclePublisher: publishes only while its node is active; before that,
a publish is dropped with rclpy's warning."""

from __future__ import annotations

from typing import Any

from rclpy.lifecycle.managed_entity import SimpleManagedEntity
from rclpy.publisher import (  # noqa: F401 - the names rclpy's module offers
    CallbackGroup,
    Publisher,
    PublisherEventCallbacks,
    QoSProfile,
)


class LifecyclePublisher(SimpleManagedEntity, Publisher):
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        SimpleManagedEntity.__init__(self)
        Publisher.__init__(self, *args, **kwargs)
        self._warned = False

    def publish(self, msg: Any) -> None:
        """Publish while the node is active; otherwise drop the message (with one
        warning).
        """
        if not self.is_activated:
            if not self._warned:  # (once, where rclpy says it at every call)
                from rclpy.logging import get_logger

                get_logger("LifecyclePublisher").warning(
                    f"Trying to publish message on the topic '{self.topic_name}', but the "
                    "publisher is not activated")
                self._warned = True
            return
        self._warned = False
        Publisher.publish(self, msg)
