"""The lifecycle nodes on the graph, and their lifecycle services called from the command
line."""

from __future__ import annotations

from launcher.bus import graph, keys
from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean

GET_STATE = "/get_state"


def lifecycle_nodes() -> list[str]:
    session = open_session("client")
    try:
        return sorted({e.topic[:-len(GET_STATE)] for e in graph.entities(session,
                                                                         space=keys.ROS)
                       if e.kind == keys.SERVICE and e.topic.endswith(GET_STATE) and
                       e.type_name == "lifecycle_msgs/srv/GetState"})
    finally:
        session.close()


def checked_node(name: str) -> str:
    known = lifecycle_nodes()
    node = name if name.startswith("/") else f"/{name}"
    if node not in known:
        raise LaunchError(f"Node not found: '{node}' is not a lifecycle node on the graph"
                          f"{did_you_mean(node, known)}; lifecycle nodes: "
                          f"{', '.join(known) or 'none'}")
    return node


def call_node(node: str, service: str, type_name: str, values: dict | None = None) -> object:
    client_node = Node("_launcher_lifecycle", argv=[], parameter_services=False)
    try:
        client = client_node.create_client(type_name, f"{node}/{service}")
        return client.call(build(f"{type_name}_Request", values or {}), 5.0)
    finally:
        client_node.destroy_node()


def available_transitions(node: str, everything: bool) -> list[object]:
    service = "get_transition_graph" if everything else "get_available_transitions"
    return list(call_node(node, service, "lifecycle_msgs/srv/GetAvailableTransitions")
                .available_transitions)
