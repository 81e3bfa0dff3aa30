"""rospy.topics: Publisher and Subscriber, which may be made before init_node (they join the
graph when it is called)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus.qos import QoS
from launcher.compat import rosidl
from rospy.core import state
from rospy.exceptions import ROSException


def build_message(data_class: Any, args: tuple, kwargs: dict) -> Any:
    """A message of `data_class` from a call's arguments (one message, or its fields)."""
    if len(args) == 1 and not kwargs and isinstance(args[0], data_class):
        return args[0]
    return data_class(*args, **kwargs)


class _Endpoint:
    """What a Publisher and a Subscriber share: the type, the name, and joining the graph at
    `init_node` when made before it."""

    def __init__(self, name: str, data_class: Any, qos: QoS) -> None:
        if not isinstance(data_class, type) or not hasattr(data_class, "_TYPE"):
            raise ValueError(f"data_class [{data_class}] is not a message data class")
        self.data_class, self.type = data_class, rosidl.type_name_of(data_class)
        self._qos, self._given, self._bus = qos, name, None
        self.name = self.resolved_name = name

    def _join(self) -> None:
        with state.lock:
            if state.node is None:
                state.pending.append(self)
            else:
                self._attach(state.node)

    def _attach(self, node: Any) -> None:
        raise NotImplementedError

    def unregister(self) -> None:
        if self._bus is not None:
            self._bus.destroy()
            self._bus = None


class Publisher(_Endpoint):
    def __init__(self, name: str, data_class: Any, subscriber_listener: Any = None,
                 tcp_nodelay: bool = False, latch: bool = False, headers: Any = None,
                 queue_size: int | None = None) -> None:
        super().__init__(name, data_class, QoS(depth=1, transient_local=True) if latch else
                         QoS(depth=max(queue_size or 10, 1)))
        self._join()

    def _attach(self, node: Any) -> None:
        self._bus = node.create_publisher(self.type, self._given, self._qos)
        self.name = self.resolved_name = self._bus.topic

    def publish(self, *args: Any, **kwargs: Any) -> None:
        """Publish a message, or one made from the arguments (its fields)."""
        if self._bus is None:
            raise ROSException("ROS node has not been initialized yet. Please call "
                               "init_node() first")
        if state.shutdown.is_set():
            raise ROSException("publish() to a closed topic")
        message = build_message(self.data_class, args, kwargs)
        self._bus.publish(message)

    def get_num_connections(self) -> int:
        """How many subscriptions the topic has."""
        return 0 if self._bus is None else self._bus.get_subscription_count()


class Subscriber(_Endpoint):
    def __init__(self, name: str, data_class: Any, callback: Callable[..., Any] | None = None,
                 callback_args: Any = None, queue_size: int | None = None,
                 buff_size: int = 65536, tcp_nodelay: bool = False) -> None:
        super().__init__(name, data_class, QoS(depth=max(queue_size or 10, 1)))
        self.callback, self.callback_args = callback, callback_args
        self._callbacks: list[tuple[Callable[..., Any], Any]] = []
        if callback is not None:
            self._callbacks.append((callback, callback_args))
        self._join()

    def _attach(self, node: Any) -> None:
        type_name = self.type

        def deliver(converted: Any) -> None:
            for callback, extra in list(self._callbacks):
                if extra is None:
                    callback(converted)
                else:
                    callback(converted, extra)
        # latched publishers' last message reaches late subscribers, as in ROS 1
        qos = QoS(depth=self._qos.depth, transient_local=True)
        self._bus = node.create_subscription(type_name, self._given, deliver, qos,
                                             make=rosidl.make)
        self.name = self.resolved_name = self._bus.topic

    def get_num_connections(self) -> int:
        """0: launcher's graph does not count a subscriber's publishers."""
        return 0




def attach_pending(node: Any) -> None:
    """init_node's part: the publishers and subscribers made before it join the graph."""
    for entity in state.pending:
        entity._attach(node)
    state.pending.clear()
