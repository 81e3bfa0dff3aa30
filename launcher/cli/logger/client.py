"""A node's logger services (rcl_interfaces' Get/SetLoggerLevels), called from the command
line."""

from __future__ import annotations

from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.errors import LaunchError

NAMES = {0: "UNSET", 10: "DEBUG", 20: "INFO", 30: "WARN", 40: "ERROR", 50: "FATAL"}


def call_node(node: str, service: str, values: dict) -> object:
    client_node = Node("_launcher_logger", argv=[], parameter_services=False)
    try:
        client = client_node.create_client(f"rcl_interfaces/srv/{service}",
                                           f"{node}/{service_name(service)}")
        if not client.wait_for_service(3.0):
            raise LaunchError(f"{node} offers no {service_name(service)} service: start it with "
                              "enable_logger_service=True (rclpy) to change its levels")
        return client.call(build(f"rcl_interfaces/srv/{service}_Request", values), 5.0)
    finally:
        client_node.destroy_node()


def service_name(service: str) -> str:
    return {"GetLoggerLevels": "get_logger_levels",
            "SetLoggerLevels": "set_logger_levels"}[service]


def logger_name(node: str, given: str | None) -> str:
    return given or node.strip("/").replace("/", ".")
