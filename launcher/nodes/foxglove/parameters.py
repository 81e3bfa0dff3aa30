"""The graph's nodes' parameters as foxglove_bridge serves them: `node.name`, got and set
through each node's parameter services, and those clients subscribe to sent when they change
(looked at with the graph, each second)."""

from __future__ import annotations

import re
import threading
from collections.abc import Callable
from typing import Any

from launcher.bus import graph
from launcher.bus.node import Node
from launcher.errors import LaunchError
from launcher.nodes.foxglove.settings import allowed

SERVICE_WAIT = 5.0  # s a parameter service call waits for its node
PARAMETER_WAIT = 1.0  # s a node's parameter services are waited for


class NodeParameters:
    def __init__(self, node: Node, whitelist: list[re.Pattern[str]], foxglove: Any,
                 warn_once: Callable[[str, str], None]) -> None:
        self.node, self.whitelist, self._foxglove, self.warn_once = \
            node, whitelist, foxglove, warn_once
        self._watched: dict[str, Any] = {}  # name -> last value sent
        self._busy = threading.Lock()

    @property
    def wanted(self) -> bool:
        """Whether a client waits for changes and none is being looked for now."""
        return bool(self._watched) and not self._busy.locked()

    def get(self, wanted: list[str]) -> list[Any]:
        """`node.name` parameters; all of every node when `wanted` is empty."""
        from launcher.bus import parameters

        found = []
        for node_name, values in self._by_node(wanted).items():
            for name, value in values.items():
                full = f"{node_name}.{name}"
                if allowed(full, self.whitelist):
                    found.append(self._foxglove.Parameter(
                        full, value=parameters.from_message(value)))
        return found

    def _by_node(self, wanted: list[str]) -> dict[str, dict[str, Any]]:
        by_node: dict[str, list[str] | None] = {}
        if wanted:
            for full in wanted:
                node_name, _, name = full.partition(".")
                listed = by_node.setdefault(node_name, [])
                if listed is not None and name:
                    listed.append(name)
        else:
            for entity in graph.nodes(self.node.graph_session()):
                if not entity.node.startswith("_"):
                    by_node[entity.node_fqn] = None
        out: dict[str, dict[str, Any]] = {}
        for node_name, listed in by_node.items():
            try:
                out[node_name] = self._read_node(node_name, listed)
            except LaunchError:
                continue  # a node gone, or one that does not answer: left out
        return out

    def _read_node(self, node_name: str, listed: list[str] | None) -> dict[str, Any]:
        client = self.node.create_client("rcl_interfaces/srv/ListParameters",
                                         f"{node_name}/list_parameters")
        getter = self.node.create_client("rcl_interfaces/srv/GetParameters",
                                         f"{node_name}/get_parameters")
        try:
            if listed is None:
                answer = client.call(self.node.message(
                    "rcl_interfaces/srv/ListParameters_Request"), PARAMETER_WAIT)
                listed = list(answer.result.names)
            answer = getter.call(self.node.message(
                "rcl_interfaces/srv/GetParameters_Request", names=listed), PARAMETER_WAIT)
            return dict(zip(listed, answer.values, strict=False))
        finally:
            client.destroy()
            getter.destroy()

    def set(self, given: list[Any]) -> list[Any]:
        from launcher.bus import parameters

        by_node: dict[str, list[Any]] = {}
        for parameter in given:
            node_name, _, name = parameter.name.partition(".")
            if not allowed(parameter.name, self.whitelist):
                continue
            by_node.setdefault(node_name, []).append(self.node.message(
                "rcl_interfaces/msg/Parameter", name=name,
                value=parameters.to_message(parameter.get_value())))
        for node_name, items in by_node.items():
            setter = self.node.create_client("rcl_interfaces/srv/SetParameters",
                                             f"{node_name}/set_parameters")
            try:
                setter.call(self.node.message("rcl_interfaces/srv/SetParameters_Request",
                                              parameters=items), SERVICE_WAIT)
            except LaunchError as exc:
                self.warn_once(f"set {node_name}", f"parameters of {node_name}: {exc}")
            finally:
                setter.destroy()
        return self.get([p.name for p in given])

    def watch(self, names: list[str], on: bool) -> None:
        """Clients subscribed to these parameters (or left them): their changes are sent
        at each look at the graph."""
        for name in names:
            if on:
                self._watched.setdefault(name, None)
            else:
                self._watched.pop(name, None)

    def send_changed(self, server: Any) -> None:
        """Send the server the watched parameters that changed since they were last sent."""
        with self._busy:
            changed = []
            for parameter in self.get(list(self._watched)):
                value = parameter.get_value()
                if self._watched.get(parameter.name) != value:
                    self._watched[parameter.name] = value
                    changed.append(parameter)
            if changed:
                server.publish_parameter_values(changed)
