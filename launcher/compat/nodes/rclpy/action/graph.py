"""rclpy.action.graph: the actions of the graph, and of one node, found by their send_goal
services (as rcl_action finds them)."""

from __future__ import annotations

from typing import Any

SUFFIX = "/_action/send_goal"


def _actions(services: list[tuple[str, list[str]]]) -> list[tuple[str, list[str]]]:
    found: dict[str, set[str]] = {}
    for name, types in services:
        if name.endswith(SUFFIX):
            found.setdefault(name[:-len(SUFFIX)], set()).update(
                t.removesuffix("_SendGoal") for t in types)
    return sorted((name, sorted(types)) for name, types in found.items())


def get_action_names_and_types(node: Any) -> list[tuple[str, list[str]]]:
    """Every action of the graph with its types: [(name, [type, …])]."""
    return _actions(node.get_service_names_and_types())


def get_action_server_names_and_types_by_node(node: Any, remote_node_name: str,
                                              remote_node_namespace: str
                                              ) -> list[tuple[str, list[str]]]:
    """The actions the node `remote_node_namespace/remote_node_name` serves, with their
    types (NodeNameNonExistentError if it is not on the graph)."""
    return _actions(node.get_service_names_and_types_by_node(remote_node_name,
                                                             remote_node_namespace))


def get_action_client_names_and_types_by_node(node: Any, remote_node_name: str,
                                              remote_node_namespace: str
                                              ) -> list[tuple[str, list[str]]]:
    """The actions the node is a client of, with their types."""
    return _actions(node.get_client_names_and_types_by_node(remote_node_name,
                                                            remote_node_namespace))


from launcher.compat.finder import rest_from_layout  # noqa: E402 - the rest of the real module's names

__getattr__ = rest_from_layout(__name__)
