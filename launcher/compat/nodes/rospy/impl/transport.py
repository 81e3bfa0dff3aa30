"""rospy.impl.transport: the abstract interfaces of a topic's connection (Transport) and of
a protocol (ProtocolHandler), as rospy defines them. launcher's bus carries messages itself,
so it implements neither; code that subclasses them still imports and runs."""

from __future__ import annotations

import itertools
from collections.abc import Callable
from typing import Any

INBOUND = "i"
OUTBOUND = "o"
BIDIRECTIONAL = "b"
_ids = itertools.count(1)  # (next() on a count is atomic in CPython)


class Transport:
    """One connection, in a `direction` (INBOUND, OUTBOUND or BIDIRECTIONAL)."""

    transport_type = "UNKNOWN"

    def __init__(self, direction: str, name: str = "unnamed") -> None:
        self.name, self.direction = name, direction
        self.done = False
        self.cleanup_cb: Callable[[Transport], Any] | None = None
        self.endpoint_id = ""
        self.id = next(_ids)
        self.stat_bytes = self.stat_num_msg = 0
        self.local_endpoint: tuple[Any, Any] = (0, 0)
        self.remote_endpoint: tuple[Any, Any] = (0, 0)

    def fileno(self) -> int | None:
        """A file descriptor for select(), if the transport has one."""
        return None

    def set_cleanup_callback(self, cleanup_callback: Callable[[Transport], Any]) -> None:
        """Call `cleanup_callback(transport)` when the transport closes."""
        self.cleanup_cb = cleanup_callback

    def close(self) -> None:
        self.done = True
        if self.cleanup_cb:
            self.cleanup_cb(self)

    def write_data(self, data: bytes) -> None:
        raise NotImplementedError("Transport.write_data: a subclass sends the data")

    def get_transport_info(self) -> str:
        raise NotImplementedError


class DeadTransport(Transport):
    """What is left of a closed transport: its statistics."""

    def __init__(self, transport: Transport) -> None:
        super().__init__(transport.direction, transport.name)
        self.transport_type = transport.transport_type
        self.id, self.endpoint_id = transport.id, transport.endpoint_id
        self.stat_bytes, self.stat_num_msg = transport.stat_bytes, transport.stat_num_msg
        self.local_endpoint = transport.local_endpoint
        self.remote_endpoint = transport.remote_endpoint
        self.done = True

    def get_transport_info(self) -> str:
        return (f"Closed {self.transport_type} connection on port {self.local_endpoint[1]} "
                f"to [{self.remote_endpoint[0]}:{self.remote_endpoint[1]}]")


class ProtocolHandler:
    """The interface of a protocol's connection maker."""

    def shutdown(self) -> None:
        pass

    def create_transport(self, topic: str, pub_uri: str, protocol_params: Any) -> Any:
        raise NotImplementedError("ProtocolHandler.create_transport: a subclass makes it")

    def supports(self, protocol: str) -> bool:
        return False

    def get_supported(self) -> list[Any]:
        return []

    def init_publisher(self, topic: str, protocol: Any) -> Any:
        raise NotImplementedError("ProtocolHandler.init_publisher: a subclass answers")
