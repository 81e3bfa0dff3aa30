"""The nodes rosnode finds on the graph."""

from __future__ import annotations

from launcher.bus import graph, keys
from launcher.bus.names import expand
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean


def graph_entities() -> list[keys.Entity]:
    session = open_session("client")
    try:
        return graph.entities(session)
    finally:
        session.close()


def node_names(entities: list[keys.Entity], hidden: bool = False) -> list[str]:
    return sorted({e.node_fqn for e in entities if hidden or not e.node.startswith("_")})


def known_node(name: str, entities: list[keys.Entity]) -> str:
    name = expand(name)
    names = node_names(entities, hidden=True)
    if name not in names:
        raise LaunchError(f"Unknown node [{name}]{did_you_mean(name, names)}")
    return name
