"""rclpy.service_introspection: a service's or client's events on `<service>/_service_event`
(`pkg/srv/Name_Event`): REQUEST_SENT and RESPONSE_RECEIVED from a client, REQUEST_RECEIVED and
RESPONSE_SENT from a service, with the request and response when the state is CONTENTS,
without them for METADATA, and none when OFF (as rclpy's configure_introspection)."""

from __future__ import annotations

import enum
import itertools
import threading
import time
from typing import Any

REQUEST_SENT, REQUEST_RECEIVED, RESPONSE_SENT, RESPONSE_RECEIVED = range(4)


class ServiceIntrospectionState(enum.IntEnum):
    OFF = 0
    METADATA = 1
    CONTENTS = 2


class Introspection:
    """What one service or client says of its calls, once configured."""

    def __init__(self, node: Any, service_name: str, srv_type: Any, gid: bytes) -> None:
        self._node, self._name, self._srv_type, self._gid = node, service_name, srv_type, gid
        self._publisher: Any = None
        self._state = ServiceIntrospectionState.OFF
        self._clock: Any = None
        self._sequence = itertools.count(1)
        self._lock = threading.Lock()

    def configure(self, clock: Any, qos: Any, state: Any) -> None:
        from launcher.bus.types import registry
        from launcher.compat import rosidl
        from rclpy.qos import to_launcher

        state = ServiceIntrospectionState(int(state))
        with self._lock:
            if state == ServiceIntrospectionState.OFF:
                if self._publisher is not None:
                    self._publisher.destroy()
                self._publisher, self._state = None, state
                return
            if self._publisher is None:
                event = registry().service_event(rosidl.type_name_of(self._srv_type))
                self._publisher = self._node.handle.create_publisher(
                    event, f"{self._name}/_service_event", to_launcher(qos))
            self._state, self._clock = state, clock

    def next_sequence(self) -> int:
        return next(self._sequence)

    def say(self, event_type: int, sequence: int, request: Any = None,
            response: Any = None) -> None:
        with self._lock:
            publisher, state = self._publisher, self._state
        if publisher is None:
            return
        from builtin_interfaces.msg import Time

        now = self._clock.now().nanoseconds if self._clock is not None else time.time_ns()
        contents = state == ServiceIntrospectionState.CONTENTS
        publisher.publish(publisher_message(
            self._node, publisher.type_name,
            info={"event_type": event_type,
                  "stamp": Time(sec=now // 1_000_000_000, nanosec=now % 1_000_000_000),
                  "client_gid": list(self._gid), "sequence_number": sequence},
            request=[request] if contents and request is not None else [],
            response=[response] if contents and response is not None else []))


def publisher_message(node: Any, type_name: str, **fields: Any) -> Any:
    from launcher.compat import rosidl

    cls = rosidl.message_class(type_name)
    info_cls = rosidl.message_class("service_msgs/msg/ServiceEventInfo")
    return cls(info=info_cls(**fields.pop("info")), **fields)
