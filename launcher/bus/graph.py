"""What is on the bus: nodes, topics and their types, and the hosts they run on, from
liveliness tokens."""

from __future__ import annotations

from collections import defaultdict

import zenoh

from launcher.bus import keys
from launcher.records import dataclass, field


@dataclass
class TopicInfo:
    name: str
    types: set[str] = field(default_factory=set)
    publishers: list[keys.Entity] = field(default_factory=list)
    subscribers: list[keys.Entity] = field(default_factory=list)


def entities(session: zenoh.Session, timeout: float = 1.0,
             space: keys.Space = keys.ROS, selector: str = "") -> list[keys.Entity]:
    """The graph's entities (or those whose tokens match `selector`, a liveliness key
    expression: a question about one name costs one name's tokens, not the whole graph's)."""
    found = []
    for reply in session.liveliness().get(selector or f"{space.liveliness}/{keys.domain()}/**",
                                          timeout=timeout):
        if reply.ok is not None:
            entity = keys.parse_liveliness(str(reply.ok.key_expr))
            if entity is not None:
                found.append(entity)
    return found


def servers(session: zenoh.Session, service: str, type_name: str, timeout: float = 0.5,
            space: keys.Space = keys.ROS) -> list[keys.Entity]:
    """The servers of `service` (any service of `type_name` when it is empty)."""
    return entities(session, timeout, space,
                    keys.servers_selector(keys.domain(), service, type_name, space))


def topics(session: zenoh.Session, space: keys.Space = keys.ROS) -> dict[str, TopicInfo]:
    table: dict[str, TopicInfo] = defaultdict(lambda: TopicInfo(""))
    for entity in entities(session, space=space):
        if entity.kind not in (keys.PUBLISHER, keys.SUBSCRIPTION):
            continue
        info = table[entity.topic]
        info.name = entity.topic
        info.types.add(entity.type_name)
        (info.publishers if entity.kind == keys.PUBLISHER else info.subscribers).append(entity)
    return dict(table)


def nodes(session: zenoh.Session) -> list[keys.Entity]:
    return [e for e in entities(session) if e.kind == keys.NODE]


def hosts(session: zenoh.Session, timeout: float = 1.0) -> dict[str, str]:
    """Which host each session runs on (its zid → the host's name), as launcher's sessions
    say (keys.host_key); a session of another program (rmw_zenoh's) says nothing."""
    found = {}
    for reply in session.liveliness().get(keys.hosts_selector(keys.domain()), timeout=timeout):
        if reply.ok is not None:
            said = keys.parse_host_key(str(reply.ok.key_expr))
            if said is not None:
                found[said[0]] = said[1]
    return found
