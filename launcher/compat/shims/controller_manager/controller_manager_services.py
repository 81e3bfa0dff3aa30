"""Calls to a controller manager's services from an rclpy node, as controller_manager's own
module offers them."""

from __future__ import annotations

from typing import Any

from controller_manager_msgs.srv import ListControllers, ListHardwareComponents


class ServiceNotFoundError(Exception):
    pass


def service_caller(node: Any, service_name: str, service_type: Any, request: Any,
                   service_timeout: float = 0.0, call_timeout: float = 10.0) -> Any:
    """The response of one call of `service_name`; ServiceNotFoundError when no server
    answers within `service_timeout` seconds (0: wait on), RuntimeError when the call takes
    longer than `call_timeout`."""
    import rclpy

    client = node.create_client(service_type, service_name)
    try:
        if not client.wait_for_service(timeout_sec=service_timeout or None):
            raise ServiceNotFoundError(f"Could not contact service {service_name}")
        future = client.call_async(request)
        rclpy.spin_until_future_complete(node, future, timeout_sec=call_timeout)
        if future.result() is None:
            raise RuntimeError(f"Could not successfully call service {service_name}")
        return future.result()
    finally:
        node.destroy_client(client)


def list_controllers(node: Any, controller_manager_name: str, service_timeout: float = 0.0,
                     call_timeout: float = 10.0) -> Any:
    """The manager's controllers (controller_manager_msgs ListControllers' response)."""
    return service_caller(node, f"{controller_manager_name}/list_controllers",
                          ListControllers, ListControllers.Request(), service_timeout,
                          call_timeout)


def list_hardware_components(node: Any, controller_manager_name: str,
                             service_timeout: float = 0.0, call_timeout: float = 10.0) -> Any:
    """The manager's hardware components."""
    return service_caller(node, f"{controller_manager_name}/list_hardware_components",
                          ListHardwareComponents, ListHardwareComponents.Request(),
                          service_timeout, call_timeout)
