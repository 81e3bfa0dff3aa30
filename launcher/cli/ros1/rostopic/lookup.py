"""The topics rostopic finds on the graph, and `/topic/field` names."""

from __future__ import annotations

from typing import Any

from launcher.bus import graph
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean


def topic_table() -> dict[str, graph.TopicInfo]:
    session = open_session("client")
    try:
        return graph.topics(session)
    finally:
        session.close()


def published_topic(topic: str, topics: dict[str, graph.TopicInfo]) -> graph.TopicInfo:
    info = topics.get(topic)
    if info is None:
        raise LaunchError(f"unknown topic '{topic}'{did_you_mean(topic, topics)}")
    return info


def split_field(name: str, topics: dict[str, Any]) -> tuple[str, str | None]:
    """`/odom/pose/pose` → ('/odom', 'pose.pose') when /odom is a topic and the whole is not,
    as rostopic reads `echo /topic/field`."""
    if name in topics:
        return name, None
    parts = name.split("/")
    for cut in range(len(parts) - 1, 1, -1):
        head = "/".join(parts[:cut])
        if head in topics:
            return head, ".".join(parts[cut:])
    return name, None
