"""rospy.topics: Publisher and Subscriber, which may be made before init_node (they join the
graph when it is called), and what rospy.topics re-exports (rospy.core's names)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus.qos import QoS
from launcher.compat import rosidl
from rospy.core import *  # noqa: F403 (rospy.topics re-exports rospy.core)
from rospy.core import __getattr__, state  # noqa: F401 (NullHandler, made when asked for)
from rospy.exceptions import ROSException, ROSSerializationException, TransportTerminated  # noqa: F401
from rospy.impl.registration import (  # noqa: F401 (rospy.topics has them)
    Registration,
    get_registration_listeners,
    get_topic_manager,
    set_topic_manager,
)

Message = rosidl.Message
DEFAULT_BUFF_SIZE = 65536  # a Subscriber's default buff_size
python3 = True  # (rospy's flag of the Python it runs on)


def args_kwds_to_message(data_class: Any, args: Any, kwds: Any) -> Any:
    """A `data_class` message from a call's arguments: the one message given as it is, else
    one made from the fields given by position or by keyword (not both: TypeError)."""
    if args and kwds:
        raise TypeError("publish() can be called with arguments or keywords, but not both.")
    if kwds:
        return data_class(**kwds)
    if len(args) == 1:
        arg = args[0]
        if isinstance(arg, data_class):
            return arg
        if isinstance(arg, rosidl.Message) and not getattr(data_class, "_FIELDS", ()):
            raise TypeError(f"expected [] but got [{rosidl.type_name_of(arg)}]")
    return data_class(*args)


class Topic:
    """What a Publisher and a Subscriber share: the type, the name, and joining the graph at
    `init_node` when made before it. `reg_type`: Registration.PUB or Registration.SUB."""

    def __init__(self, name: str, data_class: Any, reg_type: str,
                 qos: QoS | None = None) -> None:
        if not name or not isinstance(name, str):
            raise ValueError("topic name is not a non-empty string")
        if not isinstance(data_class, type) or not hasattr(data_class, "_TYPE"):
            raise ValueError(f"data_class [{data_class}] is not a message data class")
        self.data_class, self.type = data_class, rosidl.type_name_of(data_class)
        self.reg_type = reg_type
        self._qos, self._given, self._bus = qos or QoS(depth=10), name, None
        self.name = self.resolved_name = name

    def _join(self) -> None:
        with state.lock:
            if state.node is None:
                state.pending.append(self)
            else:
                self._attach(state.node)

    def _attach(self, node: Any) -> None:
        raise NotImplementedError

    def _joined(self, bus: Any) -> None:
        self._bus = bus
        self.name = self.resolved_name = bus.topic
        get_registration_listeners().notify_added(self.resolved_name, self.type,
                                                  self.reg_type)

    def get_num_connections(self) -> int:
        """How many endpoints are connected (0 here: Publisher counts its own)."""
        return 0

    def unregister(self) -> None:
        """Leave the graph (a second call does nothing)."""
        if self._bus is not None:
            self._bus.destroy()
            self._bus = None
            get_registration_listeners().notify_removed(self.resolved_name, self.type,
                                                        self.reg_type)


class SubscribeListener:
    """What a Publisher's `subscriber_listener` may override: told when a subscriber comes
    and goes."""

    def peer_subscribe(self, topic_name: str, topic_publish: Callable[[Any], Any],
                       peer_publish: Callable[[Any], Any]) -> None:
        """A subscriber came; `topic_publish(msg)` publishes to all, `peer_publish(msg)` to it."""

    def peer_unsubscribe(self, topic_name: str, num_peers: int) -> None:
        """A subscriber went; `num_peers` are left."""


class Publisher(Topic):
    def __init__(self, name: str, data_class: Any, subscriber_listener: Any = None,
                 tcp_nodelay: bool = False, latch: bool = False, headers: Any = None,
                 queue_size: int | None = None) -> None:
        super().__init__(name, data_class, Registration.PUB,
                         QoS(depth=1, transient_local=True) if latch else
                         QoS(depth=max(queue_size or 10, 1)))
        self._join()

    def _attach(self, node: Any) -> None:
        self._joined(node.create_publisher(self.type, self._given, self._qos))

    def publish(self, *args: Any, **kwargs: Any) -> None:
        """Publish a message, or one made from the arguments (its fields)."""
        if self._bus is None:
            raise ROSException("ROS node has not been initialized yet. Please call "
                               "init_node() first")
        if state.shutdown.is_set():
            raise ROSException("publish() to a closed topic")
        message = args_kwds_to_message(self.data_class, args, kwargs)
        self._bus.publish(message)

    def get_num_connections(self) -> int:
        """How many subscriptions the topic has."""
        return 0 if self._bus is None else self._bus.get_subscription_count()


class Subscriber(Topic):
    def __init__(self, name: str, data_class: Any, callback: Callable[..., Any] | None = None,
                 callback_args: Any = None, queue_size: int | None = None,
                 buff_size: int = DEFAULT_BUFF_SIZE, tcp_nodelay: bool = False) -> None:
        super().__init__(name, data_class, Registration.SUB,
                         QoS(depth=max(queue_size or 10, 1)))
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
        self._joined(node.create_subscription(type_name, self._given, deliver, qos,
                                              make=rosidl.make))

    def get_num_connections(self) -> int:
        """0: launcher's graph does not count a subscriber's publishers."""
        return 0


class Poller:
    """Which of some file descriptors have hung up or failed (select.poll), as rospy watches
    its sockets. Not thread-safe."""

    def __init__(self) -> None:
        import select

        self._select = select
        self.poller = select.poll()

    def add_fd(self, fd: Any) -> None:
        """Watch `fd`."""
        self.poller.register(fd)

    def remove_fd(self, fd: Any) -> None:
        """Stop watching `fd`."""
        self.poller.unregister(fd)

    def error_iter(self) -> Any:
        """The descriptors in error or hung up, now."""
        failed = self._select.POLLHUP | self._select.POLLERR
        for fd, event in self.poller.poll(0):
            if event & failed:
                yield fd


def attach_pending(node: Any) -> None:
    """init_node's part: the publishers and subscribers made before it join the graph."""
    for entity in state.pending:
        entity._attach(node)
    state.pending.clear()
