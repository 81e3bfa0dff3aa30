"""The actions an `action` verb finds on the graph (by their send_goal services)."""

from __future__ import annotations

from launcher.bus import actions as protocol
from launcher.bus import graph, keys
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean

SEND_GOAL = protocol.endpoint("", protocol.SEND_GOAL)  # how an action's send_goal name ends


def send_goal_endpoints() -> list[keys.Entity]:
    session = open_session("client")
    try:
        return [e for e in graph.entities(session, space=keys.ROS)
                if e.kind in (keys.SERVICE, keys.CLIENT) and e.topic.endswith(SEND_GOAL)]
    finally:
        session.close()


def actions_served(found: list[keys.Entity]) -> dict[str, set[str]]:
    """{action name: its types} of the actions that have a server."""
    actions: dict[str, set[str]] = {}
    for entity in found:
        if entity.kind == keys.SERVICE:
            actions.setdefault(entity.topic[:-len(SEND_GOAL)], set()).add(
                entity.type_name.removesuffix("_SendGoal"))
    return actions


def action_types(name: str, found: list[keys.Entity]) -> set[str]:
    actions = actions_served(found)
    if name not in actions:
        raise LaunchError(f"unknown action '{name}'{did_you_mean(name, list(actions))}; "
                          f"{listing_text(actions)}")
    return actions[name]


def listing_text(actions: dict[str, set[str]]) -> str:
    return f"the graph's actions: {', '.join(sorted(actions))}" if actions else \
        "the graph has no action servers"
