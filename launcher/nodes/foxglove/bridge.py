"""The graph served to Foxglove clients through the Foxglove SDK, as ROS 2's foxglove_bridge
serves it: a node like any other, never in the sim.

- every topic (its type known, allowed by `topic_whitelist`, hidden ones with
  `include_hidden`) is a channel: encoding `cdr`, schema `pkg/msg/Type` in `ros2msg`, the
  type's full concatenated text; the bus's CDR bytes go out as they came;
- a channel is subscribed on the bus while a client subscribes to it, and not otherwise;
  latched publishers (robot_description, tf_static) are read transient-local;
- clientPublish: a client's advertised channel (cdr) becomes a publisher; each message must
  decode as its type, else it is dropped with a warning;
- services (`service_whitelist`) are the SDK's services, their CDR passed both ways;
- parameters of every node (`param_whitelist`): parameters.py;
- time from /clock under use_sim_time; the connection graph; assets (assets.py).
Its own parameters are settings.py's; the SDK's events reach it through listener.py.
Each client's queue is the SDK's (bounded: a slow client loses frames, never slows the bus).
"""

from __future__ import annotations

import re
import threading
import time
from typing import Any

from launcher.bus import graph, keys, names
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.bus.types import normalize, registry
from launcher.bus.wire import stamp_nanoseconds
from launcher.errors import LaunchError
from launcher.nodes.foxglove.parameters import SERVICE_WAIT, NodeParameters
from launcher.nodes.foxglove.settings import Settings, allowed

SYNC_PERIOD = 1.0  # s between looks at the graph's topics and services
QOS_LOOKUP = 5.0  # s a lookup of a topic's publishers (their QoS) may take


class Bridge:
    """The graph's side of the bridge: channels, subscriptions, publishers, services and
    parameters, driven by the SDK's callbacks (ServerListener) and the graph."""

    def __init__(self, node: Node, settings: Settings) -> None:
        import foxglove

        self._foxglove = foxglove
        self.node, self.settings = node, settings
        self.server: Any = None  # the SDK's, once started
        self._lock = threading.RLock()
        self._channels: dict[str, tuple[Any, str]] = {}  # topic -> (channel, type)
        self._watched: dict[str, tuple[Any, int]] = {}  # topic -> (bus subscription, count)
        self._published: dict[tuple[int, int], tuple[Any, str, str]] = {}
        self._services: dict[str, str] = {}  # name -> type
        self._clients: dict[str, Any] = {}  # service name -> bus client
        self._warned: set[str] = set()
        self._graph_watched = False
        self._clock_time = 0
        self.parameters = NodeParameters(node, settings.params, foxglove, self._warn_once)

    # --- the graph --------------------------------------------------------------------
    def sync(self) -> None:
        """Channels and services for what the graph has now; gone ones removed."""
        entities = graph.entities(self.node.graph_session())
        topics: dict[str, str] = {}
        services: dict[str, str] = {}
        for entity in entities:
            if entity.kind == keys.PUBLISHER and self._shown(entity.topic, self.settings.topics):
                topics.setdefault(entity.topic, entity.type_name)
            elif entity.kind == keys.SERVICE and self._shown(entity.topic,
                                                             self.settings.services):
                services.setdefault(entity.topic, entity.type_name)
        with self._lock:
            for topic in [t for t in self._channels if t not in topics]:
                self._drop_channel(topic)
            for topic, type_name in topics.items():
                if topic not in self._channels:
                    self._add_channel(topic, type_name)
            if self.server is not None and "services" in self.settings.capabilities:
                self._sync_services(services)
        if self._graph_watched and self.server is not None:
            self.server.publish_connection_graph(self._connection_graph(entities))
        if self.server is not None and self.parameters.wanted:
            # (apart from the node's executor: the bridge's own parameters are read through
            # its services, which that executor answers)
            threading.Thread(target=self.parameters.send_changed, args=(self.server,),
                             daemon=True).start()

    def _shown(self, name: str, patterns: list[re.Pattern[str]]) -> bool:
        return (self.settings.include_hidden or not names.hidden(name)) and \
            allowed(name, patterns)

    def _schema(self, type_name: str) -> Any:
        try:
            text = registry().definition(type_name)
        except Exception as exc:  # noqa: BLE001 - an unknown or unreadable type: said once
            self._warn_once(type_name, f"no schema for {type_name} ({exc}): its topics are "
                                       "not served")
            return None
        return self._foxglove.Schema(name=type_name, encoding="ros2msg", data=text.encode())

    def _add_channel(self, topic: str, type_name: str) -> None:
        schema = self._schema(type_name)
        if schema is not None:
            channel = self._foxglove.Channel(topic, schema=schema, message_encoding="cdr")
            self._channels[topic] = (channel, type_name)

    def _drop_channel(self, topic: str) -> None:
        channel, _ = self._channels.pop(topic)
        watched = self._watched.pop(topic, None)
        if watched is not None:
            watched[0].destroy()
        channel.close()

    def _sync_services(self, services: dict[str, str]) -> None:
        gone = [name for name in self._services if name not in services]
        if gone:
            self.server.remove_services(gone)
            for name in gone:
                self._services.pop(name)
                self._clients.pop(name, None)
        added = []
        for name, type_name in services.items():
            if name in self._services:
                continue
            request = self._schema(f"{type_name}_Request")
            response = self._schema(f"{type_name}_Response")
            if request is None or response is None:
                continue
            self._services[name] = type_name
            added.append(self._foxglove.Service(
                name, schema=self._foxglove.ServiceSchema(
                    type_name,
                    request=self._foxglove.MessageSchema(encoding="cdr", schema=request),
                    response=self._foxglove.MessageSchema(encoding="cdr", schema=response)),
                handler=self._call))
        if added:
            self.server.add_services(added)

    def _connection_graph(self, entities: list[keys.Entity]) -> Any:
        made = self._foxglove.ConnectionGraph()
        sides: dict[tuple[str, str], set[str]] = {}
        for entity in entities:
            if entity.kind in (keys.PUBLISHER, keys.SUBSCRIPTION, keys.SERVICE):
                sides.setdefault((entity.kind, entity.topic), set()).add(entity.node_fqn)
        for (kind, name), nodes in sides.items():
            {keys.PUBLISHER: made.set_published_topic, keys.SUBSCRIPTION:
             made.set_subscribed_topic, keys.SERVICE: made.set_advertised_service}[kind](
                name, sorted(nodes))
        return made

    # --- subscriptions ----------------------------------------------------------------
    def subscribe(self, topic: str) -> None:
        with self._lock:
            found = self._channels.get(topic)
            if found is None:
                return
            if topic in self._watched:
                subscription, count = self._watched[topic]
                self._watched[topic] = (subscription, count + 1)
                return
            channel, type_name = found
            log, now = channel.log, self._now

            def forward(payload: bytes) -> None:
                log(payload, log_time=now())

            subscription = self.node.create_subscription(
                type_name, topic, forward, qos=self._qos(topic), raw=True, inline=True)
            self._watched[topic] = (subscription, 1)

    def unsubscribe(self, topic: str) -> None:
        with self._lock:
            watched = self._watched.get(topic)
            if watched is None:
                return
            subscription, count = watched
            if count > 1:
                self._watched[topic] = (subscription, count - 1)
                return
            del self._watched[topic]
            subscription.destroy()

    def _qos(self, topic: str) -> QoS:
        """Transient local where a publisher latches (robot_description, tf_static), the
        deepest publisher's depth up to max_qos_depth."""
        latched, depth = False, 1
        # (the topic's publishers alone, given time: a reply cut short by a busy machine
        # read a latched topic as volatile, and its one message was never seen)
        for entity in graph.entities(self.node.graph_session(), QOS_LOOKUP,
                                     selector=keys.endpoints_selector(keys.domain(),
                                                                      keys.PUBLISHER, topic)):
            if entity.kind == keys.PUBLISHER and entity.topic == topic:
                parsed = keys.parse_qos_key(entity.qos)
                if parsed is not None:
                    latched = latched or parsed[1]
                    depth = max(depth, parsed[2])
        return QoS(depth=min(depth, self.settings.max_qos_depth), reliable=True,
                   transient_local=latched)

    def _now(self) -> int:
        return self._clock_time if self.settings.use_sim_time and self._clock_time \
            else time.time_ns()

    def on_clock(self, message: Any) -> None:
        self._clock_time = stamp_nanoseconds(message.clock)
        if self.server is not None:
            self.server.broadcast_time(self._clock_time)

    # --- what clients publish -----------------------------------------------------------
    def advertise(self, client: int, channel: Any) -> None:
        if channel.encoding != "cdr":
            self._warn_once(f"encoding {channel.encoding}", f"a client advertised "
                            f"{channel.topic} in '{channel.encoding}': only cdr is taken")
            return
        if not allowed(channel.topic, self.settings.client_topics):
            self._warn_once(f"client topic {channel.topic}", f"a client may not publish "
                            f"{channel.topic} (client_topic_whitelist)")
            return
        try:
            type_name = registry().ensure(normalize(channel.schema_name))
        except LaunchError:
            self._warn_once(f"type {channel.schema_name}", f"a client advertised "
                            f"{channel.topic} as '{channel.schema_name}': no such type")
            return
        with self._lock:
            publisher = self.node.create_publisher(type_name, channel.topic)
            self._published[(client, channel.id)] = (publisher, type_name, channel.topic)

    def unadvertise(self, client: int, channel_id: int) -> None:
        with self._lock:
            found = self._published.pop((client, channel_id), None)
        if found is not None:
            found[0].destroy()

    def publish(self, client: int, channel_id: int, data: bytes) -> None:
        found = self._published.get((client, channel_id))
        if found is None:
            self._warn_once(f"unadvertised {client}", "a client published on a channel it "
                            "did not advertise: dropped")
            return
        publisher, type_name, topic = found
        try:
            registry().deserialize(data, type_name)
        except Exception:  # noqa: BLE001 - what the client sent is not a message of the type
            self._warn_once(f"bad data {topic}", f"a client's message on {topic} is not a "
                            f"{type_name} in CDR: dropped (and every such one after it)")
            return
        publisher.publish_raw(data)

    # --- services -----------------------------------------------------------------------
    def _call(self, request: Any) -> bytes:
        name = request.service_name
        type_name = self._services.get(name)
        if type_name is None:
            raise LaunchError(f"service {name} is gone")
        client = self._clients.get(name)
        if client is None:
            client = self._clients[name] = self.node.create_client(type_name, name)
        return client.call_raw(bytes(request.payload), SERVICE_WAIT)

    # --- the rest -----------------------------------------------------------------------
    def watch_graph(self, on: bool) -> None:
        self._graph_watched = on

    def _warn_once(self, key: str, text: str) -> None:
        if key not in self._warned:
            self._warned.add(key)
            self.node.get_logger().warning(text)
