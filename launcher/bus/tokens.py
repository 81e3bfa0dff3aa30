"""Liveliness tokens as rmw_zenoh writes them, read with plain strings (the layout is told in
keys.py, which builds its Entity from these).

The listing commands' fast path (cli/quick.py) reads the graph through this alone: keys.py's
classes cost more to import than the listing itself takes.
"""

from __future__ import annotations

ROS = "@ros2_lv"  # the ROS 2 graph's first chunk
SIM = "@sim_lv"  # the simulator's own (Gazebo's side)
NODE, PUBLISHER, SUBSCRIPTION, SERVICE, CLIENT = "NN", "MP", "MS", "SS", "SC"


def mangle(name: str) -> str:
    return name.replace("/", "%") if name else "%"


def unmangle(name: str) -> str:
    return "" if name == "%" else name.replace("%", "/")


def fields(key: str) -> list[str] | None:
    """[zid, nid, eid, kind, enclave, namespace, node, then topic, type, hash, qos for an
    endpoint] of a token of either graph (names still mangled); None if it is not one."""
    parts = key.split("/")
    if len(parts) < 9 or parts[0] not in (ROS, SIM):
        return None
    return parts[2:]


def endpoint(key: str) -> tuple[str, str] | None:
    """(kind, topic or service name) of an endpoint's token; None for a node's, or no
    token."""
    parts = fields(key)
    return (parts[3], unmangle(parts[7])) if parts is not None and len(parts) >= 10 else None


def hidden(name: str) -> bool:
    """ROS 2's hidden names: a part that begins with '_' (ros2cli leaves them out of its
    lists, as /fibonacci/_action/feedback)."""
    return any(part.startswith("_") for part in name.split("/"))
