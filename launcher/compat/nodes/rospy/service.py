"""rospy.service: Service, ServiceProxy and wait_for_service (rospy.impl.tcpros_service's in
rospy), the node's ServiceManager, and what rospy.service re-exports (rospy.core's names)."""

from __future__ import annotations

import threading
import time as _time
from collections.abc import Callable
from typing import Any

from launcher.compat import rosidl
from rospy.core import *  # noqa: F403 (rospy.service re-exports rospy.core)
from rospy.core import __getattr__, need_node, state  # noqa: F401 (NullHandler, when asked)
from rospy.exceptions import ROSException, ROSInterruptException, ServiceException
from rospy.impl.registration import (  # noqa: F401 (rospy.service has them)
    Registration,
    get_registration_listeners,
    get_service_manager,
    set_service_manager,
)
from rospy.impl.transport import *  # noqa: F403 (rospy.service re-exports it)
from rospy.topics import args_kwds_to_message


class ServiceManager:
    """The node's services by resolved name; registration listeners hear of each."""

    def __init__(self, registration_listeners: Any = None) -> None:
        self.map: dict[str, Any] = {}
        self.lock = threading.RLock()
        self.registration_listeners = registration_listeners or get_registration_listeners()

    def get_services(self) -> list[tuple[str, Any]]:
        """[(name, uri), …] of the services."""
        with self.lock:
            return [(name, service.uri) for name, service in self.map.items()]

    def unregister_all(self) -> None:
        """Forget every service."""
        self.map.clear()

    def register(self, resolved_service_name: str, service: Any) -> None:
        """Add a service; ServiceException when the name has one already."""
        with self.lock:
            taken = resolved_service_name in self.map
            if not taken:
                self.map[resolved_service_name] = service
            self.registration_listeners.notify_added(resolved_service_name, service.uri,
                                                     Registration.SRV)
        if taken:
            raise ServiceException(f"service [{resolved_service_name}] already registered")

    def unregister(self, resolved_service_name: str, service: Any) -> None:
        """Forget a service (if it is the one registered under the name)."""
        with self.lock:
            if self.map.get(resolved_service_name) is service:
                del self.map[resolved_service_name]
            self.registration_listeners.notify_removed(resolved_service_name, service.uri,
                                                       Registration.SRV)

    def get_service(self, resolved_service_name: str) -> Any:
        """The service registered under the name, or None."""
        return self.map.get(resolved_service_name)


set_service_manager(ServiceManager())


def convert_return_to_response(response: Any, response_class: Any) -> Any:
    """A service handler's return as a `response_class` message: the message itself, or
    one made from a dict's fields, a list's or tuple's, or a single value (None:
    ServiceException)."""
    if isinstance(response, response_class):
        return response
    if response is None:
        raise ServiceException("service handler returned None")
    try:
        if isinstance(response, dict):
            return response_class(**response)
        if isinstance(response, list | tuple):
            return response_class(*response)
        return response_class(response)
    except (AttributeError, TypeError) as exc:
        raise ServiceException(f"handler returned invalid value: {exc}") from None


class Service:
    def __init__(self, name: str, service_class: Any, handler: Callable[[Any], Any],
                 buff_size: int = 65536, error_handler: Any = None) -> None:
        self.service_class, self.handler = service_class, handler
        self.type = rosidl.type_name_of(service_class)
        node = need_node("Service")

        def answer(request: Any, _given: Any) -> Any:
            return convert_return_to_response(handler(request), service_class.Response)
        self._bus = node.create_service(self.type, name, answer, make=rosidl.make,
                                        new_response=service_class.Response)
        self.resolved_name, self.uri = self._bus.name, None  # (no ROSRPC URI: the bus's)
        get_service_manager().register(self.resolved_name, self)

    def shutdown(self, reason: str = "") -> None:
        """Stop serving."""
        if self._bus is not None:
            self._bus.destroy()
            self._bus = None
            get_service_manager().unregister(self.resolved_name, self)

    def spin(self) -> None:
        """Block until the node shuts down."""
        while not state.shutdown.wait(0.2):
            pass


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

        request = args_kwds_to_message(self.request_class, args, kwargs)
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
