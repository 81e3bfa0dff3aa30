"""The Foxglove SDK's ServerListener for a Bridge: each client's event handed to the bridge
(its parameters to the bridge's NodeParameters). An error in one is said and never reaches the
SDK: the other clients go on. Imported when the server starts (the SDK is a heavy import)."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from foxglove.websocket import ServerListener

from launcher.nodes.foxglove.bridge import Bridge


def guarded(fallback: Any = None) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """A listener method whose error is logged as the client's doing, answering `fallback`."""
    def wrap(method: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(method)
        def run(self: Listener, *args: Any, **kwargs: Any) -> Any:
            try:
                return method(self, *args, **kwargs)
            except Exception as exc:  # noqa: BLE001 - a client's doing: said, not raised
                self.bridge.node.get_logger().warning(f"foxglove client: {exc}")
                return fallback
        return run
    return wrap


class Listener(ServerListener):
    def __init__(self, bridge: Bridge) -> None:
        self.bridge = bridge

    @guarded()
    def on_subscribe(self, client: Any, channel: Any) -> None:
        self.bridge.subscribe(channel.topic)

    @guarded()
    def on_unsubscribe(self, client: Any, channel: Any) -> None:
        self.bridge.unsubscribe(channel.topic)

    @guarded()
    def on_client_advertise(self, client: Any, channel: Any) -> None:
        self.bridge.advertise(client.id, channel)

    @guarded()
    def on_client_unadvertise(self, client: Any, channel_id: int) -> None:
        self.bridge.unadvertise(client.id, channel_id)

    @guarded()
    def on_message_data(self, client: Any, channel_id: int, data: bytes) -> None:
        self.bridge.publish(client.id, channel_id, data)

    @guarded([])
    def on_get_parameters(self, client: Any, names: Any, request_id: Any = None) -> list[Any]:
        return self.bridge.parameters.get(list(names))

    @guarded([])
    def on_set_parameters(self, client: Any, parameters: Any,
                          request_id: Any = None) -> list[Any]:
        return self.bridge.parameters.set(list(parameters))

    @guarded()
    def on_parameters_subscribe(self, names: Any) -> None:
        self.bridge.parameters.watch(list(names), True)

    @guarded()
    def on_parameters_unsubscribe(self, names: Any) -> None:
        self.bridge.parameters.watch(list(names), False)

    @guarded()
    def on_connection_graph_subscribe(self) -> None:
        self.bridge.watch_graph(True)

    @guarded()
    def on_connection_graph_unsubscribe(self) -> None:
        self.bridge.watch_graph(False)
