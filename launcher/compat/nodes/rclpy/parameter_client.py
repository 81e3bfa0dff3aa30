"""rclpy.parameter_client.AsyncParameterClient: another node's parameters through its
parameter services (`<node>/list_parameters`, `get_parameters`, `set_parameters`,
`describe_parameters`, …); each call returns a Future of the service's response."""

from __future__ import annotations

from typing import Any

from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.client import Client  # noqa: F401
from rclpy.event_handler import SubscriptionEventCallbacks  # noqa: F401
from rclpy.node import Node  # noqa: F401
from rclpy.parameter import Parameter, parameter_dict_from_yaml_file
from rclpy.qos import QoSProfile  # noqa: F401
from rclpy.subscription import MessageInfo, Subscription  # noqa: F401
from rclpy.task import Future  # noqa: F401


class AsyncParameterClient:
    def __init__(self, node: Any, remote_node_name: str, qos_profile: Any = None,
                 callback_group: Any = None) -> None:
        from rcl_interfaces.srv import (
            DescribeParameters,
            GetParameters,
            ListParameters,
            SetParameters,
        )

        self._node = node
        name = remote_node_name if remote_node_name.startswith("/") else \
            f"/{remote_node_name}"
        self.remote_node_name = name
        make = node.create_client
        self._list = make(ListParameters, f"{name}/list_parameters",
                          callback_group=callback_group)
        self._get = make(GetParameters, f"{name}/get_parameters",
                         callback_group=callback_group)
        self._set = make(SetParameters, f"{name}/set_parameters",
                         callback_group=callback_group)
        self._describe = make(DescribeParameters, f"{name}/describe_parameters",
                              callback_group=callback_group)
        self._clients = [self._list, self._get, self._set, self._describe]

    def services_are_ready(self) -> bool:
        """Whether the remote node's parameter services are there."""
        return all(c.service_is_ready() for c in self._clients)

    def wait_for_services(self, timeout_sec: float | None = None) -> bool:
        """Wait for them up to `timeout_sec`; whether they came."""
        return all(c.wait_for_service(timeout_sec) for c in self._clients)

    def list_parameters(self, prefixes: list[str] | None = None, depth: int | None = None,
                        callback: Any = None) -> Any:
        """A Future of the remote node's ListParameters response."""
        request = self._list.srv_type.Request(prefixes=list(prefixes or []),
                                              depth=depth or 0)
        return self._call(self._list, request, callback)

    def get_parameters(self, names: list[str], callback: Any = None) -> Any:
        """A Future of the values of `names`."""
        return self._call(self._get, self._get.srv_type.Request(names=list(names)), callback)

    def set_parameters(self, parameters: list[Parameter], callback: Any = None) -> Any:
        """A Future of setting `parameters` (one result each)."""
        request = self._set.srv_type.Request(
            parameters=[p.to_parameter_msg() if isinstance(p, Parameter) else p
                        for p in parameters])
        return self._call(self._set, request, callback)

    def describe_parameters(self, names: list[str], callback: Any = None) -> Any:
        """A Future of the descriptors of `names`."""
        return self._call(self._describe,
                          self._describe.srv_type.Request(names=list(names)), callback)

    def get_parameter_types(self, names: list[str], callback: Any = None) -> Any:
        """A Future of the types of `names`."""

        described = self.describe_parameters(names)
        future = Future(executor=self._node.executor)

        def done(answer: Any) -> None:
            try:
                future.set_result(type("GetParameterTypesResponse", (), {
                    "types": [d.type for d in answer.result().descriptors]})())
            except Exception as exc:
                future.set_exception(exc)
        described.add_done_callback(done)
        if callback is not None:
            future.add_done_callback(callback)
        return future

    def delete_parameters(self, names: list[str], callback: Any = None) -> Any:
        """Deleting is setting to NOT_SET, as rclpy's client does."""
        from rcl_interfaces.msg import Parameter as Message
        from rcl_interfaces.msg import ParameterValue

        request = self._set.srv_type.Request(parameters=[
            Message(name=n, value=ParameterValue(type=0)) for n in names])
        return self._call(self._set, request, callback)

    def load_parameter_file(self, parameter_file: str, use_wildcard: bool = False,
                            callback: Any = None) -> Any:
        """A Future of setting the values a params file gives
        the remote node.
        """
        values = parameter_dict_from_yaml_file(parameter_file, use_wildcard)  # (as rclpy)
        request = self._set.srv_type.Request(parameters=list(values.values()))
        return self._call(self._set, request, callback)

    def _call(self, client: Any, request: Any, callback: Any) -> Any:
        future = client.call_async(request)
        if callback is not None:
            future.add_done_callback(callback)
        return future


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
