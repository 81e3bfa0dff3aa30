"""The rmw_zenoh wire layout, in one place so it can follow rmw_zenoh versions.

    topic key      <domain>/<topic>/<pkg>::msg::dds_::<Type>_/RIHS01_<sha256>
    service key    <domain>/<service>/<pkg>::srv::dds_::<Type>_/RIHS01_<sha256>
    liveliness     @ros2_lv/<domain>/<zid>/<nid>/<eid>/<NN|MP|MS|SS|SC>/<enclave>/<ns>/<node>
                   [/<topic>/<type>/<hash>/<qos>]        ('/' inside a name is written '%')
    qos            <reliability>:<durability>:<history>,<depth>:<deadline s>,<ns>:<lifespan
                   s>,<ns>:<liveliness>,<lease s>,<ns>   (six parts, as rmw_zenoh writes them
                   since its 2024 releases; a part equal to its default profile is left empty,
                   so the usual profile is `::,10:,:,:,,`); the older `1:2:1,10` is still read
    attachment     int64 sequence number, int64 source timestamp (ns), a byte 16, 16-byte GID
    latched        zenoh-ext's advanced publisher and subscriber on the topic key (their own
                   `<key>/@adv/…` keys), as rmw_zenoh makes transient local endpoints

Followed: rmw_zenoh_cpp's rolling branch as of late 2025 (liveliness_utils.cpp,
rmw_publisher_data.cpp, rmw_subscription_data.cpp, attachment_helpers.cpp).

The simulator's own topics and services (Gazebo's gz-transport side) use the same layout
under other first chunks, `@sim/<domain>/…` and `@sim_lv/…`, so that they stay off the ROS
graph (`@` chunks match no wildcard) and the bridge and the `gz` tools find them (SIM).

Which host a session runs on is launcher's own token, off the ROS graph too (no tool of ROS 2
lists it, nor does zenoh-ros2-sdk):

    host           @launcher_lv/<domain>/<zid>/host/<host name>
"""

from __future__ import annotations

import os
import struct

from launcher.bus import places
from launcher.bus.tokens import (  # noqa: F401 - the names keys' users know
    CLIENT,
    NODE,
    PUBLISHER,
    SERVICE,
    SUBSCRIPTION,
    fields,
    mangle,
    unmangle,
)
from launcher.bus.tokens import ROS as LIVELINESS
from launcher.bus.tokens import SIM as SIM_LIVELINESS
from launcher.records import dataclass


def domain() -> int:
    """The ROS domain, $ROS_DOMAIN_ID, read when a key is made (a node may set it before it
    makes its node, and a warm-started process imported this module before its environment
    was its own); checked (0–232) where sessions open (discovery.domain_id): a bad one is
    said there."""
    return places.domain(os.environ) or 0


@dataclass(frozen=True)
class Space:
    """Where a graph's keys and tokens live: ROS 2's, or the simulator's own."""

    data: str  # the first chunk of topic and service keys, before the domain ("" for ROS)
    liveliness: str

    def prefix(self, domain: int) -> str:
        return f"{self.data}{domain}"


ROS = Space("", LIVELINESS)
SIM = Space("@sim/", SIM_LIVELINESS)
_ATTACHMENT = struct.Struct("<qqB16s")


# rmw's enums: reliability 1 reliable, 2 best effort; durability 1 transient local,
# 2 volatile; history 1 keep last, 2 keep all. rmw_zenoh's default profile is reliable,
# volatile, keep last, with no deadline, lifespan or lease and automatic liveliness.
_RELIABLE, _BEST_EFFORT, _TRANSIENT_LOCAL, _VOLATILE = "1", "2", "1", "2"


def qos_key(reliable: bool, transient_local: bool, depth: int) -> str:
    """The QoS part of a liveliness token."""
    reliability = "" if reliable else _BEST_EFFORT
    durability = _TRANSIENT_LOCAL if transient_local else ""
    return f"{reliability}:{durability}:,{depth}:,:,:,,"


def parse_qos_key(text: str) -> tuple[bool, bool, int] | None:
    """(reliable, transient local, depth) of a token's QoS part (either form); None if it
    is not one."""
    parts = text.split(":")
    if len(parts) not in (3, 6):
        return None
    if len(parts) == 6 and [p.count(",") for p in parts[3:]] != [1, 1, 2]:
        return None  # deadline s,ns : lifespan s,ns : liveliness,lease s,ns
    history, _, depth = parts[2].partition(",")
    if not depth.isdigit() or parts[0] not in ("", "0", _RELIABLE, _BEST_EFFORT) or \
            parts[1] not in ("", "0", _TRANSIENT_LOCAL, _VOLATILE) or history not in ("", "0",
                                                                                   "1", "2"):
        return None
    return parts[0] != _BEST_EFFORT, parts[1] == _TRANSIENT_LOCAL, int(depth)


def dds_type(name: str) -> str:
    """`geometry_msgs/msg/Twist` -> `geometry_msgs::msg::dds_::Twist_`."""
    package, kind, message = name.split("/")
    return f"{package}::{kind}::dds_::{message}_"


def ros_type(dds: str) -> str:
    """The inverse of dds_type."""
    package, kind, _, message = dds.split("::")
    return f"{package}/{kind}/{message.rstrip('_')}"


def topic_key(domain: int, topic: str, type_name: str, type_hash: str,
              space: Space = ROS) -> str:
    return f"{space.prefix(domain)}/{topic.strip('/')}/{dds_type(type_name)}/{type_hash}"


def service_key(domain: int, service: str, type_name: str, type_hash: str,
                space: Space = ROS) -> str:
    return f"{space.prefix(domain)}/{service.strip('/')}/{dds_type(type_name)}/{type_hash}"


def split_topic_key(key: str) -> tuple[str, str, str]:
    """(topic, ROS type, hash) of a topic key (of either space)."""
    if key.startswith(SIM.data):
        key = key[len(SIM.data):]
    _, rest = key.split("/", 1)
    topic, dds, type_hash = rest.rsplit("/", 2)
    return "/" + topic, ros_type(dds), type_hash


@dataclass(frozen=True)
class Entity:
    """What a liveliness token says about a node or one of its endpoints."""

    zid: str
    node_id: int
    entity_id: int
    kind: str
    namespace: str
    node: str
    topic: str = ""
    type_name: str = ""
    type_hash: str = ""
    qos: str = ""

    @property
    def node_fqn(self) -> str:
        return f"{self.namespace.rstrip('/')}/{self.node}"


def liveliness_key(domain: int, entity: Entity, space: Space = ROS) -> str:
    parts = [space.liveliness, str(domain), entity.zid, str(entity.node_id), str(entity.entity_id),
             entity.kind, "%", mangle(entity.namespace), entity.node]
    if entity.kind != NODE:
        parts += [mangle(entity.topic), dds_type(entity.type_name), entity.type_hash,
                  entity.qos]
    return "/".join(parts)


def servers_selector(domain: int, service: str, type_name: str, space: Space = ROS) -> str:
    """The liveliness key expression of every server of `service` with `type_name` (a query
    for one service's servers, not the whole graph's tokens)."""
    service_part = mangle(service) if service else "*"
    return "/".join([space.liveliness, str(domain), "*", "*", "*", SERVICE, "*", "*", "*",
                     service_part, dds_type(type_name), "**"])


def endpoints_selector(domain: int, kind: str, topic: str, space: Space = ROS) -> str:
    """The liveliness key expression of every endpoint of `kind` (PUBLISHER, SUBSCRIPTION) on
    `topic`, of any node, type and QoS."""
    return "/".join([space.liveliness, str(domain), "*", "*", "*", kind, "*", "*", "*",
                     mangle(topic), "**"])


def parse_liveliness(key: str) -> Entity | None:
    parts = fields(key)
    if parts is None:
        return None
    zid, nid, eid, kind, _, namespace, node, *rest = parts
    entity = Entity(zid, int(nid), int(eid), kind, unmangle(namespace), node)
    if len(rest) >= 3:
        return Entity(zid, int(nid), int(eid), kind, unmangle(namespace), node,
                      unmangle(rest[0]), ros_type(rest[1]), rest[2],
                      rest[3] if len(rest) > 3 else "")
    return entity


def shutdown_key(domain: int, zid: str, node_id: int) -> str:
    """Where a node hears `rosnode kill` (launcher's own key, off the ROS graph: no tool of
    ROS 2 lists it)."""
    return f"launcher_control/{domain}/shutdown/{zid}/{node_id}"


HOSTS = "@launcher_lv"  # launcher's own tokens' first chunk
_KEY_SPECIALS = "*$?#/"  # what a chunk of a key expression cannot hold


def host_key(domain: int, zid: str, host: str) -> str:
    """The token that says which host the session `zid` runs on."""
    chunk = "".join("_" if c in _KEY_SPECIALS else c for c in host) or "_"
    return f"{HOSTS}/{domain}/{zid}/host/{chunk}"


def hosts_selector(domain: int) -> str:
    return f"{HOSTS}/{domain}/*/host/*"


def parse_host_key(key: str) -> tuple[str, str] | None:
    """(zid, host name) of a host token; None if it is not one."""
    parts = key.split("/")
    if len(parts) != 5 or parts[0] != HOSTS or parts[3] != "host":
        return None
    return parts[2], parts[4]


def attachment(sequence: int, timestamp_ns: int, gid: bytes) -> bytes:
    return _ATTACHMENT.pack(sequence, timestamp_ns, 16, gid[:16].ljust(16, b"\0"))


def parse_attachment(data: bytes) -> tuple[int, int, bytes] | None:
    if len(data) != _ATTACHMENT.size:
        return None
    sequence, stamp, length, gid = _ATTACHMENT.unpack(data)
    return (sequence, stamp, gid) if length == 16 else None
