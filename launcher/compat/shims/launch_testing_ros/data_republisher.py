"""launch_testing_ros.DataRepublisher: messages of one topic published again on another,
transformed (or dropped)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class DataRepublisher:
    """On `node`, each `msg_type` message of `listen_topic` becomes `transform_fn(message)` on
    `publish_topic` (nothing when that is falsy)."""

    def __init__(self, node: Any, listen_topic: str, publish_topic: str, msg_type: Any,
                 transform_fn: Callable[[Any], Any]) -> None:
        self._received = 0
        self._republished: list[Any] = []
        self._node, self._transform = node, transform_fn
        self._subscriber = node.create_subscription(msg_type, listen_topic, self._heard, 10)
        self._publisher = node.create_publisher(msg_type, publish_topic, 10)

    def shutdown(self) -> None:
        """Stop republishing."""
        self._node.destroy_subscription(self._subscriber)
        self._node.destroy_publisher(self._publisher)

    def get_num_received(self) -> int:
        return self._received

    def get_num_republished(self) -> int:
        """The messages published again (fewer than received when some were dropped)."""
        return len(self._republished)

    def get_republished(self) -> list[Any]:
        """The messages that were published again (as received, as launch_testing_ros
        keeps them)."""
        return self._republished

    def _heard(self, message: Any) -> None:
        self._received += 1
        transformed = self._transform(message)
        if transformed:
            self._republished.append(message)
            self._publisher.publish(transformed)


__all__ = ["DataRepublisher"]
