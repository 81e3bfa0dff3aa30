"""WaitForTopics: subscribe to topics from a node of its own (its own rclpy context, spun in
a thread) and wait until each has had a message."""

from __future__ import annotations

import contextlib
import threading
import uuid
from collections import deque
from collections.abc import Callable
from typing import Any

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node


class WaitForTopics:
    """`with WaitForTopics([("chatter", String)], timeout=5.0) as waited: …` (a RuntimeError
    when some topic had no message in time), or `wait()`, then `shutdown()`. `trigger`, when
    given, is called with its arguments once the subscriptions are up (to make the messages
    come)."""

    def __init__(self, topic_tuples: list[tuple[str, Any]], timeout: float = 5.0,
                 messages_received_buffer_length: int = 10, node_namespace: str | None = None,
                 trigger: Callable[..., Any] | None = None, *trigger_args: Any,
                 **trigger_kwargs: Any) -> None:
        self.topic_tuples, self.timeout = list(topic_tuples), timeout
        self.trigger, self.trigger_args, self.trigger_kwargs = trigger, trigger_args, \
            trigger_kwargs
        self._context = rclpy.Context()
        rclpy.init(context=self._context)
        self._executor = SingleThreadedExecutor(context=self._context)
        self._node = _Listener(f"_test_node_{uuid.uuid4().hex[:10]}", self._context,
                               messages_received_buffer_length, node_namespace)
        self._executor.add_node(self._node)
        self._spinning = threading.Thread(target=self._spin, name="wait-for-topics",
                                          daemon=True)
        self._spinning.start()

    def _spin(self) -> None:
        with contextlib.suppress(ExternalShutdownException):  # (the context shut down)
            self._executor.spin()

    def wait(self) -> bool:
        """Whether every topic had a message within the timeout."""
        self._node.listen(self.topic_tuples)
        if self.trigger is not None:
            self.trigger(self._node, *self.trigger_args, **self.trigger_kwargs)
        return self._node.all_heard.wait(self.timeout)

    def shutdown(self) -> None:
        """Stop listening: the context ends, the node goes."""
        self._context.try_shutdown()
        self._spinning.join()
        self._node.destroy_node()

    def topics_received(self) -> set[str]:
        """The topics that had at least one message."""
        return set(self._node.heard)

    def topics_not_received(self) -> set[str]:
        """The topics that had none."""
        return self._node.expected - self._node.heard

    def received_messages(self, topic_name: str) -> list[Any]:
        """The last messages of `topic_name` (KeyError when it had none)."""
        if topic_name not in self._node.messages:
            raise KeyError(f"No messages received for topic: {topic_name}")
        return list(self._node.messages[topic_name])

    def __enter__(self) -> WaitForTopics:
        if not self.wait():
            self.shutdown()
            raise RuntimeError("Did not receive messages on these topics: ",
                               self.topics_not_received())
        return self

    def __exit__(self, *_exc: Any) -> None:
        self.shutdown()


class _Listener(Node):
    def __init__(self, name: str, context: Any, depth: int, namespace: str | None) -> None:
        super().__init__(name, context=context, namespace=namespace)
        self.depth = depth
        self.expected: set[str] = set()
        self.heard: set[str] = set()
        self.messages: dict[str, deque[Any]] = {}
        self.all_heard = threading.Event()
        self.subscribed: list[tuple[str, Any]] = []

    def listen(self, topic_tuples: list[tuple[str, Any]]) -> None:
        self.all_heard.clear()
        self.heard = set()
        for kept in self.messages.values():
            kept.clear()
        for topic, type_ in topic_tuples:
            if (topic, type_) in self.subscribed:
                continue
            self.subscribed.append((topic, type_))
            self.expected.add(topic)
            self.messages[topic] = deque(maxlen=self.depth)
            self.create_subscription(type_, topic, self._heard(topic), 10)

    def _heard(self, topic: str) -> Callable[[Any], None]:
        def callback(message: Any) -> None:
            self.messages[topic].append(message)
            self.heard.add(topic)
            if self.heard >= self.expected:
                self.all_heard.set()
        return callback
