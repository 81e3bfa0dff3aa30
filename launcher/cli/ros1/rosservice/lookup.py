"""The services rosservice finds on the graph."""

from __future__ import annotations

from launcher.bus import graph, keys
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean


def service_servers() -> list[keys.Entity]:
    session = open_session("client")
    try:
        return [e for e in graph.entities(session) if e.kind == keys.SERVICE]
    finally:
        session.close()


def providers_of(name: str, servers: list[keys.Entity]) -> list[keys.Entity]:
    mine = [e for e in servers if e.topic == name]
    if not mine:
        known = sorted({e.topic for e in servers})
        raise LaunchError(f"Service [{name}] is not available{did_you_mean(name, known)}")
    return mine
