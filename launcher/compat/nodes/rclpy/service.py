"""rclpy.service.Service over launcher's bus service."""

from __future__ import annotations

from typing import Any

from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.clock import Clock  # noqa: F401
from rclpy.properties import readonly
from rclpy.qos import QoSProfile  # noqa: F401
from rclpy.service_introspection import ServiceIntrospectionState  # noqa: F401
from rclpy.type_support import Srv  # noqa: F401


class ServiceNames:
    """The names a service and its clients answer to, as rclpy's."""
    _bus: Any

    service_name = readonly("_bus.name", "The service's fully qualified name (`srv_name` "
                                         "too, rclpy's older spelling).")
    srv_name = service_name


class Service(ServiceNames):
    def __init__(self, service_impl: Any, srv_type: Any, srv_name: str, callback: Any,
                 callback_group: Any, qos_profile: Any) -> None:
        """`service_impl`: launcher's bus service (Node.create_service makes both)."""
        self._bus, self.srv_type, self.callback = service_impl, srv_type, callback
        self.callback_group, self.qos_profile = callback_group, qos_profile

    handle = readonly("_bus", "The launcher bus service under this one.")

    _introspection: Any = None

    def configure_introspection(self, clock: Any, service_event_qos_profile: Any,
                                introspection_state: Any) -> None:
        """Publish this service's events on `<name>/_service_event` (OFF, METADATA or
        CONTENTS), as rclpy's."""
        self._introspection.configure(clock, service_event_qos_profile, introspection_state)

    def destroy(self) -> None:
        """Take the service off the graph."""
        self._introspection.configure(None, None, 0)
        self._bus.destroy()
