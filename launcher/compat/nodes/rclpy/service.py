"""rclpy.service.Service over launcher's bus service."""

from __future__ import annotations

from typing import Any


class ServiceNames:
    """The names a service and its clients answer to, as rclpy's."""
    _bus: Any

    @property
    def service_name(self) -> str:
        """The service's fully qualified name."""
        return self._bus.name

    @property
    def srv_name(self) -> str:
        """The service's fully qualified name (rclpy's older spelling)."""
        return self._bus.name


class Service(ServiceNames):
    def __init__(self, bus: Any, srv_type: Any, srv_name: str, callback: Any,
                 callback_group: Any, qos_profile: Any) -> None:
        self._bus, self.srv_type, self.callback = bus, srv_type, callback
        self.callback_group, self.qos_profile = callback_group, qos_profile

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

    @property
    def handle(self) -> Any:
        """The launcher bus service under this one."""
        return self._bus
