"""rospy.service: Service, ServiceProxy and wait_for_service."""

from __future__ import annotations

import time as _time
from collections.abc import Callable
from typing import Any

from launcher.compat import rosidl
from rospy.client import spin
from rospy.core import need_node, state
from rospy.exceptions import ROSException, ROSInterruptException, ServiceException
from rospy.topics import build_message


def _response(service_class: Any, result: Any) -> Any:
    response_class = service_class.Response
    if isinstance(result, response_class):
        return result
    if result is None:
        raise ServiceException("service handler returned None")
    if isinstance(result, dict):
        return response_class(**result)
    if isinstance(result, list | tuple):
        return response_class(*result)
    return response_class(result)


class Service:
    def __init__(self, name: str, service_class: Any, handler: Callable[[Any], Any],
                 buff_size: int = 65536, error_handler: Any = None) -> None:
        self.service_class, self.handler = service_class, handler
        self.type = rosidl.type_name_of(service_class)
        node = need_node("Service")

        def answer(request: Any, _given: Any) -> Any:
            return _response(service_class, handler(request))
        self._bus = node.create_service(self.type, name, answer, make=rosidl.make,
                                        new_response=service_class.Response)
        self.resolved_name = self._bus.name

    def shutdown(self, reason: str = "") -> None:
        """Stop serving."""
        self._bus.destroy()

    def spin(self) -> None:
        """Block until the node shuts down."""
        spin()


ServiceProxyError = ServiceException


class ServiceProxy:
    def __init__(self, name: str, service_class: Any, persistent: bool = False,
                 headers: Any = None) -> None:
        self.service_class = service_class
        self.request_class, self.response_class = service_class.Request, \
            service_class.Response
        self.type = rosidl.type_name_of(service_class)
        self.resolved_name = name
        self._given, self._bus = name, None

    def _client(self) -> Any:
        if self._bus is None:
            node = need_node("ServiceProxy")
            self._bus = node.create_client(self.type, self._given, make=rosidl.make)
            self.resolved_name = self._bus.name
        return self._bus

    def wait_for_service(self, timeout: float | None = None) -> None:
        """Wait until the service is on the graph (see wait_for_service)."""
        wait_for_service(self._given, timeout)

    def call(self, *args: Any, **kwargs: Any) -> Any:
        """Call the service with a request (or its fields); its response.
        ServiceException when the call fails.
        """
        from launcher.errors import LaunchError

        request = build_message(self.request_class, args, kwargs)
        client = self._client()
        try:
            return client.call(request, 30.0)
        except LaunchError as exc:
            raise ServiceException(f"service [{self.resolved_name}] call failed: {exc}"
                                   ) from None

    __call__ = call

    def close(self) -> None:
        """Release the client."""
        if self._bus is not None:
            self._bus.destroy()
            self._bus = None


def wait_for_service(service: str, timeout: float | None = None) -> None:
    """Wait until `service` is on the graph: ROSException after `timeout` seconds,
    ROSInterruptException at shutdown.
    """
    from launcher.bus import graph, keys

    node = need_node("wait_for_service")
    name = node.resolve(service, "service name")
    end = None if timeout is None else _time.monotonic() + timeout
    while True:
        if any(e.kind == keys.SERVICE and e.topic == name
               for e in graph.entities(node.graph_session(), 0.5)):
            return
        if state.shutdown.is_set():
            raise ROSInterruptException("rospy shutdown")
        if end is not None and _time.monotonic() >= end:
            raise ROSException(f"timeout exceeded while waiting for service {name}")
        _time.sleep(0.05)
