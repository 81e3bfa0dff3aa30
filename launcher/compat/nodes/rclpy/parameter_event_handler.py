"""rclpy.parameter_event_handler: callbacks on the parameter changes nodes announce on
`/parameter_events` (rcl_interfaces/msg/ParameterEvent): for one parameter of one node, or
for every event. Callbacks run newest first, as rclpy's."""

from __future__ import annotations

import threading
from collections import defaultdict
from collections.abc import Callable, Iterable
from itertools import chain
from typing import Any

from rcl_interfaces.msg import ParameterEvent

from rclpy.callback_groups import CallbackGroup  # noqa: F401 - as rclpy's module offers it
from rclpy.qos import QoSProfile, qos_profile_parameter_events


class ParameterCallbackHandle:
    """A callback on one parameter of one node (`/ns/name`)."""

    def __init__(self, parameter_name: str, node_name: str,
                 callback: Callable[[Any], None]) -> None:
        self.parameter_name = parameter_name
        self.node_name = node_name
        self.callback = callback
        self.mutex = threading.Lock()


class ParameterEventCallbackHandle:
    """A callback on every parameter event."""

    def __init__(self, callback: Callable[[ParameterEvent], None]) -> None:
        self.callback = callback
        self.mutex = threading.Lock()


class ParameterEventHandler:
    """Listens to /parameter_events on `node` and calls the callbacks added to it."""

    def __init__(self, node: Any, qos_profile: QoSProfile = qos_profile_parameter_events,
                 callback_group: Any = None, event_callbacks: Any = None,
                 qos_overriding_options: Any = None, raw: bool = False) -> None:
        self.node = node
        self.qos_profile = qos_profile
        self._mutex = threading.Lock()
        self._parameter_callbacks: dict[tuple[str, str], list[ParameterCallbackHandle]] = \
            defaultdict(list)
        self._event_callbacks: list[ParameterEventCallbackHandle] = []
        self.parameter_event_subscription = node.create_subscription(
            ParameterEvent, "/parameter_events", self._on_event, qos_profile,
            callback_group=callback_group, event_callbacks=event_callbacks,
            qos_overriding_options=qos_overriding_options, raw=raw)

    def destroy(self) -> None:
        """Stop listening."""
        self.node.destroy_subscription(self.parameter_event_subscription)

    def _on_event(self, event: ParameterEvent) -> None:
        with self._mutex:
            by_parameter = [(key, list(handles))
                            for key, handles in self._parameter_callbacks.items()]
            every = list(self._event_callbacks)
        for (parameter_name, node_name), handles in by_parameter:
            parameter = self.get_parameter_from_event(event, parameter_name, node_name)
            if parameter is not None:
                for handle in handles:
                    with handle.mutex:
                        handle.callback(parameter)
        for handle in every:
            with handle.mutex:
                handle.callback(event)

    @staticmethod
    def get_parameter_from_event(event: ParameterEvent, parameter_name: str,
                                 node_name: str) -> Any:
        """The new or changed parameter of that name in the event of node `node_name`, or
        None."""
        if event.node == node_name:
            for parameter in chain(event.new_parameters, event.changed_parameters):
                if parameter.name == parameter_name:
                    return parameter
        return None

    @staticmethod
    def get_parameters_from_event(event: ParameterEvent) -> Iterable[Any]:
        """Every new or changed parameter of the event."""
        yield from chain(event.new_parameters, event.changed_parameters)

    def add_parameter_callback(self, parameter_name: str, node_name: str,
                               callback: Callable[[Any], None]) -> ParameterCallbackHandle:
        """Call `callback(parameter)` when that parameter of `node_name` (relative to this
        node's namespace unless it starts with `/`) is declared or set."""
        handle = ParameterCallbackHandle(parameter_name, self._resolve_path(node_name),
                                         callback)
        with self._mutex:
            self._parameter_callbacks[(parameter_name, handle.node_name)].insert(0, handle)
        return handle

    def remove_parameter_callback(self, handle: ParameterCallbackHandle) -> None:
        """Stop calling a parameter callback (RuntimeError if it is not one of these)."""
        key = (handle.parameter_name, handle.node_name)
        with self._mutex:
            if handle not in self._parameter_callbacks.get(key, []):
                raise RuntimeError("Callback doesn't exist")
            self._parameter_callbacks[key].remove(handle)
            if not self._parameter_callbacks[key]:
                del self._parameter_callbacks[key]

    def add_parameter_event_callback(self, callback: Callable[[ParameterEvent], None]
                                     ) -> ParameterEventCallbackHandle:
        """Call `callback(event)` for every parameter event."""
        handle = ParameterEventCallbackHandle(callback)
        with self._mutex:
            self._event_callbacks.insert(0, handle)
        return handle

    def remove_parameter_event_callback(self, handle: ParameterEventCallbackHandle) -> None:
        """Stop calling an event callback (RuntimeError if it is not one of these)."""
        with self._mutex:
            if handle not in self._event_callbacks:
                raise RuntimeError("Callback doesn't exist")
            self._event_callbacks.remove(handle)

    def _resolve_path(self, node_path: str | None = None) -> str:
        if not node_path:
            return self.node.get_fully_qualified_name()
        if node_path.startswith("/"):
            return node_path
        namespace = self.node.get_namespace().strip("/")
        return f"/{namespace}/{node_path}" if namespace else f"/{node_path}"


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
