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
- parameters of every node (`param_whitelist`), `node.name` as foxglove_bridge names them,
  got, set, and subscribed to (a change is sent at the next look at the graph, each second);
- time from /clock under use_sim_time; the connection graph; assets (assets.py).
Each client's queue is the SDK's (bounded: a slow client loses frames, never slows the bus).
"""

from __future__ import annotations

import re
import threading
import time
from collections.abc import Callable
from typing import Any

from launcher.bus import graph, keys, names
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.bus.types import normalize, registry
from launcher.errors import LaunchError

SYNC_PERIOD = 1.0  # s between looks at the graph's topics and services
SERVICE_WAIT = 5.0  # s a service call waits for its server
PARAMETER_WAIT = 1.0  # s a node's parameter services are waited for
CAPABILITIES = ("clientPublish", "parameters", "parametersSubscribe", "services",
                "connectionGraph", "assets")


class Settings:
    """foxglove_bridge's parameters, as a ROS user sets them."""

    def __init__(self, node: Node) -> None:
        def value(name: str, default: Any) -> Any:
            return node.declare_parameter(name, default).value

        self.port = int(value("port", 8765))
        self.address = str(value("address", "127.0.0.1"))
        self.topics = _patterns(value("topic_whitelist", [".*"]), "topic_whitelist")
        self.services = _patterns(value("service_whitelist", [".*"]), "service_whitelist")
        self.params = _patterns(value("param_whitelist", [".*"]), "param_whitelist")
        self.client_topics = _patterns(value("client_topic_whitelist", [".*"]),
                                       "client_topic_whitelist")
        self.send_buffer_limit = int(value("send_buffer_limit", 10_000_000))
        self.use_sim_time = bool(value("use_sim_time", False))
        self.capabilities = [str(c) for c in value("capabilities", list(CAPABILITIES))]
        self.include_hidden = bool(value("include_hidden", False))
        self.max_qos_depth = int(value("max_qos_depth", 25))
        from launcher.nodes.foxglove.assets import DEFAULT_ALLOWLIST

        self.asset_allowlist = [str(p) for p in value("asset_uri_allowlist",
                                                      list(DEFAULT_ALLOWLIST))]
        self.token = bool(value("token", True))
        unknown = sorted(set(self.capabilities) - set(CAPABILITIES))
        if unknown:
            raise LaunchError(f"foxglove_bridge: unknown capabilities {unknown}; expected "
                              f"some of {list(CAPABILITIES)}")
        if not 0 < self.port < 65536:
            raise LaunchError(f"foxglove_bridge: port {self.port}: expected 1 to 65535")

    @property
    def backlog(self) -> int:
        """The SDK bounds each client's queue in messages, not bytes: send_buffer_limit read
        as that many 512 KiB messages (10 MB: 19, about 10 MB of camera images), from 8 to
        1024."""
        return max(8, min(1024, self.send_buffer_limit // (512 * 1024)))


def _patterns(values: Any, name: str) -> list[re.Pattern[str]]:
    items = [values] if isinstance(values, str) else list(values)
    try:
        return [re.compile(str(item)) for item in items]
    except re.error as exc:
        raise LaunchError(f"foxglove_bridge: {name}: '{exc.pattern}' is not a regular "
                          f"expression: {exc}") from None


def _allowed(name: str, patterns: list[re.Pattern[str]]) -> bool:
    return any(p.fullmatch(name) for p in patterns)


class Bridge:
    """The graph's side of the bridge: channels, subscriptions, publishers, services and
    parameters, driven by the SDK's callbacks (ServerListener) and the graph."""

    def __init__(self, node: Node, settings: Settings) -> None:
        import foxglove

        self._foxglove = foxglove
        self.node, self.settings = node, settings
        self.server: Any = None
        self._lock = threading.RLock()
        self._channels: dict[str, tuple[Any, str]] = {}  # topic -> (channel, type)
        self._watched: dict[str, tuple[Any, int]] = {}  # topic -> (bus subscription, count)
        self._published: dict[tuple[int, int], tuple[Any, str, str]] = {}
        self._services: dict[str, str] = {}  # name -> type
        self._clients: dict[str, Any] = {}  # service name -> bus client
        self._warned: set[str] = set()
        self._graph_watched = False
        self._clock_time = 0
        self._watched_parameters: dict[str, Any] = {}  # name -> last value sent
        self._parameters_busy = threading.Lock()

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
        if self._watched_parameters and self.server is not None and \
                not self._parameters_busy.locked():
            # (apart from the node's executor: the bridge's own parameters are read through
            # its services, which that executor answers)
            threading.Thread(target=self._send_changed_parameters, daemon=True).start()

    def _shown(self, name: str, patterns: list[re.Pattern[str]]) -> bool:
        return (self.settings.include_hidden or not names.hidden(name)) and \
            _allowed(name, patterns)

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
        for entity in graph.entities(self.node.graph_session()):
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
        self._clock_time = message.clock.sec * 1_000_000_000 + message.clock.nanosec
        if self.server is not None:
            self.server.broadcast_time(self._clock_time)

    # --- what clients publish -----------------------------------------------------------
    def advertise(self, client: int, channel: Any) -> None:
        if channel.encoding != "cdr":
            self._warn_once(f"encoding {channel.encoding}", f"a client advertised "
                            f"{channel.topic} in '{channel.encoding}': only cdr is taken")
            return
        if not _allowed(channel.topic, self.settings.client_topics):
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

    # --- parameters ---------------------------------------------------------------------
    def get_parameters(self, wanted: list[str]) -> list[Any]:
        """`node.name` parameters; all of every node when `wanted` is empty."""
        from launcher.bus import parameters

        found = []
        for node_name, values in self._node_parameters(wanted).items():
            for name, value in values.items():
                full = f"{node_name}.{name}"
                if _allowed(full, self.settings.params):
                    found.append(self._foxglove.Parameter(
                        full, value=parameters.from_message(value)))
        return found

    def _node_parameters(self, wanted: list[str]) -> dict[str, dict[str, Any]]:
        by_node: dict[str, list[str] | None] = {}
        if wanted:
            for full in wanted:
                node_name, _, name = full.partition(".")
                listed = by_node.setdefault(node_name, [])
                if listed is not None and name:
                    listed.append(name)
        else:
            for entity in graph.nodes(self.node.graph_session()):
                if not entity.node.startswith("_"):
                    by_node[entity.node_fqn] = None
        out: dict[str, dict[str, Any]] = {}
        for node_name, listed in by_node.items():
            try:
                out[node_name] = self._read_node(node_name, listed)
            except LaunchError:
                continue  # a node gone, or one that does not answer: left out
        return out

    def _read_node(self, node_name: str, listed: list[str] | None) -> dict[str, Any]:
        client = self.node.create_client("rcl_interfaces/srv/ListParameters",
                                         f"{node_name}/list_parameters")
        getter = self.node.create_client("rcl_interfaces/srv/GetParameters",
                                         f"{node_name}/get_parameters")
        try:
            if listed is None:
                answer = client.call(self.node.message(
                    "rcl_interfaces/srv/ListParameters_Request"), PARAMETER_WAIT)
                listed = list(answer.result.names)
            answer = getter.call(self.node.message(
                "rcl_interfaces/srv/GetParameters_Request", names=listed), PARAMETER_WAIT)
            return dict(zip(listed, answer.values, strict=False))
        finally:
            client.destroy()
            getter.destroy()

    def set_parameters(self, given: list[Any]) -> list[Any]:
        from launcher.bus import parameters

        by_node: dict[str, list[Any]] = {}
        for parameter in given:
            node_name, _, name = parameter.name.partition(".")
            if not _allowed(parameter.name, self.settings.params):
                continue
            by_node.setdefault(node_name, []).append(self.node.message(
                "rcl_interfaces/msg/Parameter", name=name,
                value=parameters.to_message(parameter.get_value())))
        for node_name, items in by_node.items():
            setter = self.node.create_client("rcl_interfaces/srv/SetParameters",
                                             f"{node_name}/set_parameters")
            try:
                setter.call(self.node.message("rcl_interfaces/srv/SetParameters_Request",
                                              parameters=items), SERVICE_WAIT)
            except LaunchError as exc:
                self._warn_once(f"set {node_name}", f"parameters of {node_name}: {exc}")
            finally:
                setter.destroy()
        return self.get_parameters([p.name for p in given])

    def watch_parameters(self, names: list[str], on: bool) -> None:
        """Clients subscribed to these parameters (or left them): their changes are sent
        at each look at the graph."""
        for name in names:
            if on:
                self._watched_parameters.setdefault(name, None)
            else:
                self._watched_parameters.pop(name, None)

    def _send_changed_parameters(self) -> None:
        with self._parameters_busy:
            changed = []
            for parameter in self.get_parameters(list(self._watched_parameters)):
                value = parameter.get_value()
                if self._watched_parameters.get(parameter.name) != value:
                    self._watched_parameters[parameter.name] = value
                    changed.append(parameter)
            if changed:
                self.server.publish_parameter_values(changed)

    # --- the rest -----------------------------------------------------------------------
    def watch_graph(self, on: bool) -> None:
        self._graph_watched = on

    def _warn_once(self, key: str, text: str) -> None:
        if key not in self._warned:
            self._warned.add(key)
            self.node.get_logger().warning(text)


def listener(bridge: Bridge) -> Any:
    """The SDK's ServerListener, handing each event to the bridge; an error in one is said
    and never reaches the SDK (the other clients go on)."""
    from foxglove.websocket import ServerListener

    def guarded(work: Callable[..., Any], fallback: Any = None) -> Callable[..., Any]:
        def run(*args: Any) -> Any:
            try:
                return work(*args)
            except Exception as exc:  # noqa: BLE001 - a client's doing: said, not raised
                bridge.node.get_logger().warning(f"foxglove client: {exc}")
                return fallback
        return run

    class Listener(ServerListener):
        on_subscribe = staticmethod(guarded(lambda client, channel:
                                            bridge.subscribe(channel.topic)))
        on_unsubscribe = staticmethod(guarded(lambda client, channel:
                                              bridge.unsubscribe(channel.topic)))
        on_client_advertise = staticmethod(guarded(lambda client, channel:
                                                   bridge.advertise(client.id, channel)))
        on_client_unadvertise = staticmethod(guarded(lambda client, channel_id:
                                                     bridge.unadvertise(client.id,
                                                                        channel_id)))
        on_message_data = staticmethod(guarded(lambda client, channel_id, data:
                                               bridge.publish(client.id, channel_id, data)))
        on_get_parameters = staticmethod(guarded(
            lambda client, names, request_id=None: bridge.get_parameters(list(names)), []))
        on_set_parameters = staticmethod(guarded(
            lambda client, parameters, request_id=None: bridge.set_parameters(
                list(parameters)), []))
        on_parameters_subscribe = staticmethod(guarded(
            lambda names: bridge.watch_parameters(list(names), True)))
        on_parameters_unsubscribe = staticmethod(guarded(
            lambda names: bridge.watch_parameters(list(names), False)))
        on_connection_graph_subscribe = staticmethod(guarded(lambda: bridge.watch_graph(True)))
        on_connection_graph_unsubscribe = staticmethod(guarded(
            lambda: bridge.watch_graph(False)))

    return Listener()
