"""rclpy.action.get_action_names_and_types: the actions of the graph, by their send_goal
services (as rcl_action finds them)."""

from __future__ import annotations

from typing import Any

SUFFIX = "/_action/send_goal"


def get_action_names_and_types(node: Any) -> list[tuple[str, list[str]]]:
    """Every action of the graph with its types: [(name, [type, …])], found by
    their send_goal services.
    """
    found: dict[str, set[str]] = {}
    for name, types in node.get_service_names_and_types():
        if name.endswith(SUFFIX):
            found.setdefault(name[:-len(SUFFIX)], set()).update(
                t.removesuffix("_SendGoal") for t in types)
    return sorted((name, sorted(types)) for name, types in found.items())
