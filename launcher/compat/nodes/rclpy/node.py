"""rclpy.node.Node over launcher's bus node: same names, same argument order and defaults.

Each Node owns one launcher bus node (its Zenoh session, graph tokens and parameter
services). Its entities' callbacks go on the node's queue; the executor it is spun by runs
them (see executors.py). What the node holds of its own (whether it lives, its entities and
callback groups) is its Custody (custody.py), which the rest of this rclpy asks; its
parameters, as rclpy has them, are a part of their own that it mixes in (node_parameters.py).
"""

from __future__ import annotations

import functools
import sys
import time
from collections.abc import Callable
from typing import Any

from launcher.bus import components, graph, keys
from launcher.bus.node import Node as BusNode
from launcher.compat import rosidl
from launcher.errors import LaunchError
from rclpy import name_rules
from rclpy.callback_groups import (  # noqa: F401 - the names rclpy's module offers
    CallbackGroup,
    MutuallyExclusiveCallbackGroup,
    ReentrantCallbackGroup,
)
from rclpy.client import Client
from rclpy.clock import Clock, ROSClock  # noqa: F401
from rclpy.constants import S_TO_NS
from rclpy.context import Context  # noqa: F401
from rclpy.custody import Custody, grouped
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks  # noqa: F401
from rclpy.exceptions import (  # noqa: F401
    InvalidHandle,
    InvalidNamespaceException,
    InvalidNodeNameException,
    InvalidParameterTypeException,
    InvalidParameterValueException,
    InvalidTopicNameException,
    NotInitializedException,
    ParameterAlreadyDeclaredException,
    ParameterImmutableException,
    ParameterNotDeclaredException,
    ParameterUninitializedException,
)
from rclpy.expand_topic_name import expand_topic_name  # noqa: F401
from rclpy.guard_condition import GuardCondition
from rclpy.logging import RcutilsLogger, get_logger  # noqa: F401
from rclpy.matched import QoSPublisherMatchedInfo, QoSSubscriptionMatchedInfo
from rclpy.matched import watch as watch_matched
from rclpy.node_parameters import ParametersMixin
from rclpy.parameter import PARAMETER_SEPARATOR_STRING, Parameter  # noqa: F401
from rclpy.properties import readonly
from rclpy.publisher import Publisher
from rclpy.qos import QoSProfile, qos_profile_services_default, to_launcher
from rclpy.service import Service
from rclpy.service_introspection import (
    REQUEST_RECEIVED,
    RESPONSE_SENT,
    Introspection,
)
from rclpy.subscription import ContentFilterOptions, MessageInfo, Subscription  # noqa: F401
from rclpy.time_source import TimeSource
from rclpy.timer import Rate, Timer, TimerInfo  # noqa: F401
from rclpy.timer import bind as bind_timer
from rclpy.topic_endpoint_info import TopicEndpointInfo  # noqa: F401
from rclpy.type_support import (  # noqa: F401
    Srv,
    check_is_valid_msg_type,
    check_is_valid_srv_type,
)
from rclpy.utilities import get_default_context
from rclpy.validate_full_topic_name import validate_full_topic_name  # noqa: F401
from rclpy.validate_namespace import validate_namespace  # noqa: F401
from rclpy.validate_node_name import validate_node_name  # noqa: F401
from rclpy.validate_parameter_name import validate_parameter_name  # noqa: F401
from rclpy.validate_topic_name import validate_topic_name  # noqa: F401
from rclpy.waitable import Waitable  # noqa: F401

HIDDEN_NODE_PREFIX = "_"
# What rclpy's module offers that a node needs only when asked (their modules cost at import):
# looked up at first use.
_ON_USE = {"Executor": "rclpy.executors", "LoggingService": "rclpy.logging_service",
           "ParameterService": "rclpy.parameter_service",
           "TypeDescriptionService": "rclpy.type_description_service",
           "QoSOverridingOptions": "rclpy.qos_overriding_options"}


class NodeNameNonExistentError(RuntimeError):
    """Raised when a graph query names a node that is not on the graph."""


class Node(ParametersMixin):
    PARAM_REL_TOL = 1e-6

    def __init__(self, node_name: str, *, context: Any = None, cli_args: list[str] | None = None,
                 namespace: str | None = None, use_global_arguments: bool = True,
                 enable_rosout: bool = True, rosout_qos_profile: Any = None,
                 start_parameter_services: bool = True,
                 parameter_overrides: list[Parameter] | None = None,
                 allow_undeclared_parameters: bool = False,
                 automatically_declare_parameters_from_overrides: bool = False,
                 enable_logger_service: bool = False) -> None:
        within = components.current()  # loaded by a component container: its own context
        self._context = context or (within and within.context) or get_default_context()
        if not self._context.ok():
            raise NotInitializedException("cannot create node")
        argv: list[str] = []
        if use_global_arguments:
            given = self._context.args
            argv += list(sys.argv[1:] if given is None else given[1:])
        argv += list(cli_args or [])
        try:
            self._bus = BusNode(node_name, namespace=namespace or "", argv=argv,
                                parameter_services=start_parameter_services)
        except LaunchError as exc:
            raise _invalid_name(node_name, namespace or "", str(exc)) from None
        self._bus.owner = self
        self._bus.host.ring_with(self._context.bell)  # its work wakes whichever executor spins it
        self.executor: Any = None
        self._timers: list[Timer] = []
        self.default_callback_group = MutuallyExclusiveCallbackGroup()
        self._custody = Custody(self, self._bus, self.default_callback_group)
        self._logger = RcutilsLogger(
            f"{self._bus.namespace.strip('/').replace('/', '.')}.{self._bus.name}"
            if self._bus.namespace.strip("/") else self._bus.name)
        self._init_parameters(parameter_overrides, allow_undeclared_parameters,
                              automatically_declare_parameters_from_overrides)
        self._clock = ROSClock(self._bus.get_clock(),
                               follow=functools.partial(_time_source, self))
        self._context.track_node(self)
        self._start_announcing()
        if enable_logger_service:
            from rclpy.logging_service import LoggingService  # only when asked

            LoggingService(self)

    # --- identity ---------------------------------------------------------------------------
    context = readonly("_context", "The context the node belongs to (rclpy.init's, unless "
                                   "one was given).")
    handle = readonly("_bus", "The launcher bus node under this node: its graph tokens, "
                              "entities and services.")

    def get_name(self) -> str:
        """The node's name, after any `__node:=` remap."""
        return self._bus.name

    def get_namespace(self) -> str:
        """The node's namespace (`/` for none), after any `__ns:=` remap."""
        return self._bus.namespace or "/"

    def get_fully_qualified_name(self) -> str:
        """The namespace and name together: `/ns/name`."""
        return self._bus.fully_qualified_name

    def get_logger(self) -> RcutilsLogger:
        """The node's logger, named as rclpy names it (`ns.name`)."""
        return self._logger

    def get_clock(self) -> ROSClock:
        """The node's clock: ROS time, which follows `/clock` when use_sim_time is true."""
        return self._clock

    def resolve_topic_name(self, topic: str, *, only_expand: bool = False) -> str:
        """A topic name as the node resolves it: relative names joined to the namespace,
        `~` to the node's name, and the command line's remaps applied.

        :param topic: the name to resolve.
        :param only_expand: accepted for rclpy's signature; remaps are always applied.
        :return: the fully qualified topic name.
        """
        return self._bus.resolve(topic)

    def resolve_service_name(self, service: str, *, only_expand: bool = False) -> str:
        """A service name as the node resolves it (see resolve_topic_name).

        :param service: the name to resolve.
        :param only_expand: accepted for rclpy's signature.
        :return: the fully qualified service name.
        """
        return self._bus.resolve(service, "service name")

    @property
    def callback_groups(self) -> list[CallbackGroup]:
        """The callback groups the node's entities run in, the default one first."""
        return list(self._custody.groups)

    def add_waitable(self, waitable: Any) -> None:
        """Waitables are not supported: raises NotImplementedError."""
        raise NotImplementedError("waitables are not supported by launcher's rclpy")

    # --- endpoints --------------------------------------------------------------------------
    def create_publisher(self, msg_type: Any, topic: str, qos_profile: QoSProfile | int,
                         *, callback_group: Any = None, event_callbacks: Any = None,
                         qos_overriding_options: Any = None,
                         publisher_class: Any = Publisher) -> Publisher:
        """A publisher of `msg_type` on `topic`.

        :param msg_type: the message class.
        :param topic: the topic's name, resolved as resolve_topic_name does.
        :param qos_profile: a QoSProfile, or a history depth.
        :param callback_group: the group its event callbacks run in.
        :param event_callbacks: PublisherEventCallbacks (`matched` is called as subscriptions
            come and go).
        :return: the Publisher.
        """
        self._custody.check_alive()
        if qos_overriding_options is not None:
            qos_profile = self._overridden(qos_profile, "publisher", topic,
                                           qos_overriding_options)
        qos = to_launcher(qos_profile)
        bus = self._bus.create_publisher(rosidl.type_name_of(msg_type), topic, qos)
        publisher = publisher_class(bus, msg_type, topic, qos_profile, event_callbacks)
        self._custody.entities.append(publisher)
        self._watch_matches(event_callbacks, bus, QoSPublisherMatchedInfo, callback_group)
        return publisher

    def _overridden(self, qos_profile: QoSProfile | int, kind: str, topic: str,
                    options: Any) -> QoSProfile:
        """The QoS with the policies `options` names taken from their parameters."""
        from rclpy.qos_overriding_options import declare_qos_parameters  # only when asked

        if not isinstance(qos_profile, QoSProfile):
            qos_profile = QoSProfile(depth=int(qos_profile))
        return declare_qos_parameters(kind, self, self.resolve_topic_name(topic), qos_profile,
                                      options)

    def _watch_matches(self, event_callbacks: Any, bus: Any, info: type, group: Any) -> None:
        """A matched-event callback, if given: told as the other side of the bus endpoint
        comes and goes (until the endpoint is destroyed)."""
        matched = getattr(event_callbacks, "matched", None)
        if matched is not None:
            watch_matched(bus, info, grouped(self, group, matched))

    def create_subscription(self, msg_type: Any, topic: str, callback: Callable[[Any], Any],
                            qos_profile: QoSProfile | int, *, callback_group: Any = None,
                            event_callbacks: Any = None, qos_overriding_options: Any = None,
                            raw: bool = False, content_filter_options: Any = None,
                            ) -> Subscription:
        """A subscription: `callback(message)` runs on the node's executor for each message.

        :param msg_type: the message class.
        :param topic: the topic's name.
        :param callback: called with each message (or its serialized bytes with `raw=True`).
        :param qos_profile: a QoSProfile, or a history depth.
        :param callback_group: the group the callback runs in (default: the node's).
        :param event_callbacks: SubscriptionEventCallbacks.
        :param raw: hand the callback the serialized message.
        :return: the Subscription.
        """
        self._custody.check_alive()
        if qos_overriding_options is not None:
            qos_profile = self._overridden(qos_profile, "subscription", topic,
                                           qos_overriding_options)
        type_name = rosidl.type_name_of(msg_type)
        made: list[Any] = []
        run = grouped(self, callback_group, callback, lambda: made[0] if made else None)
        if not raw:
            rosidl.message_class(type_name)  # made now, not on the first message
        bus = self._bus.create_subscription(type_name, topic, run, to_launcher(qos_profile),
                                            raw=raw, make=rosidl.make)
        subscription = Subscription(bus, msg_type, topic, callback, callback_group,
                                    qos_profile, raw, event_callbacks)
        made.append(subscription)
        self._custody.entities.append(subscription)
        self._watch_matches(event_callbacks, bus, QoSSubscriptionMatchedInfo, callback_group)
        return subscription

    def create_service(self, srv_type: Any, srv_name: str,
                       callback: Callable[[Any, Any], Any], *,
                       qos_profile: QoSProfile = qos_profile_services_default,
                       callback_group: Any = None) -> Service:
        """A service: `callback(request, response)` fills and returns the response.

        :param srv_type: the service class.
        :param srv_name: the service's name.
        :param callback: called on the node's executor for each request.
        :param qos_profile: accepted for rclpy's signature.
        :param callback_group: the group the callback runs in.
        :return: the Service.
        """
        self._custody.check_alive()
        type_name = rosidl.type_name_of(srv_type)

        introspection = Introspection(self, self._bus.resolve(srv_name, "service name"),
                                      srv_type, bytes(16))

        def answer(request: Any, response: Any) -> Any:
            sequence = introspection.next_sequence()
            introspection.say(REQUEST_RECEIVED, sequence, request=request)
            result = callback(request, response)
            if result is None:
                raise RuntimeError("the service callback returned None: return the response")
            introspection.say(RESPONSE_SENT, sequence, response=result)
            return result
        bus = self._bus.create_service(type_name, srv_name,
                                       grouped(self, callback_group, answer),
                                       make=rosidl.make, new_response=srv_type.Response)
        service = Service(bus, srv_type, srv_name, callback, callback_group, qos_profile)
        service._introspection = introspection
        self._custody.entities.append(service)
        return service

    def create_client(self, srv_type: Any, srv_name: str, *,
                      qos_profile: QoSProfile = qos_profile_services_default,
                      callback_group: Any = None) -> Client:
        """A client of `srv_name`: `call_async(request)` returns a Future of the response.

        :param srv_type: the service class.
        :param srv_name: the service's name.
        :param qos_profile: accepted for rclpy's signature.
        :param callback_group: the group its done callbacks run in.
        :return: the Client.
        """
        self._custody.check_alive()
        bus = self._bus.create_client(rosidl.type_name_of(srv_type), srv_name,
                                      make=rosidl.make)
        rosidl.service_class(rosidl.type_name_of(srv_type))
        client = Client(self._context, bus, srv_type, srv_name, qos_profile, callback_group,
                        node=self)
        self._custody.entities.append(client)
        return client

    def create_timer(self, timer_period_sec: float, callback: Callable[[], Any],
                     callback_group: Any = None, clock: Any = None,
                     autostart: bool = True) -> Timer:
        """A timer that calls `callback` every `timer_period_sec` seconds on the executor.

        :param timer_period_sec: the period, in seconds.
        :param callback: called with no arguments each period.
        :param callback_group: the group it runs in.
        :param clock: the clock whose time it keeps (default: the node's, sim time when
            use_sim_time is true).
        :param autostart: start it now (false: it waits for reset()).
        :return: the Timer.
        """
        self._custody.check_alive()
        if timer_period_sec <= 0:
            raise ValueError(f"timer period must be > 0, got {timer_period_sec}")
        timer = Timer(callback, callback_group, int(timer_period_sec * 1e9), clock or
                      self._clock, context=self._context, autostart=autostart)
        bind_timer(timer, grouped(self, callback_group, callback, lambda: timer))
        self._timers.append(timer)
        if self.executor is not None:
            self.executor.wake()
        return timer

    def create_rate(self, frequency: float, clock: Any = None) -> Rate:
        """A Rate that sleeps so that a loop runs `frequency` times a second.

        :param frequency: loops a second.
        :param clock: the clock whose time it keeps (default: the node's, sim time when
            use_sim_time is true).
        :return: the Rate.
        """
        if frequency <= 0:
            raise ValueError("frequency must be > 0")
        timer = Timer(None, None, int(S_TO_NS / frequency), clock or self._clock,
                      context=self._context, autostart=False)
        return Rate(timer, context=self._context)

    def create_guard_condition(self, callback: Callable[[], Any],
                               callback_group: Any = None) -> GuardCondition:
        """A guard condition: each `trigger()` runs `callback` once on the executor.

        :param callback: called with no arguments.
        :param callback_group: the group it runs in.
        :return: the GuardCondition.
        """
        guard = GuardCondition(callback, callback_group, self._context, host=self._bus.host,
                               run=grouped(self, callback_group, callback))
        self._custody.entities.append(guard)
        return guard

    # --- destroying -------------------------------------------------------------------------
    def _destroy_entity(self, entity: Any) -> bool:
        if entity in self._custody.entities:
            self._custody.entities.remove(entity)
            entity.destroy()
            return True
        return False

    def destroy_publisher(self, publisher: Publisher) -> bool:
        """Destroy a publisher of this node; False if it was not one of its own."""
        return self._destroy_entity(publisher)

    def destroy_subscription(self, subscription: Subscription) -> bool:
        """Destroy a subscription of this node; False if it was not one of its own."""
        return self._destroy_entity(subscription)

    def destroy_service(self, service: Service) -> bool:
        """Destroy a service of this node; False if it was not one of its own."""
        return self._destroy_entity(service)

    def destroy_client(self, client: Client) -> bool:
        """Destroy a client of this node; False if it was not one of its own."""
        return self._destroy_entity(client)

    def destroy_guard_condition(self, guard: GuardCondition) -> bool:
        """Destroy a guard condition of this node; False if it was not its own."""
        return self._destroy_entity(guard)

    def destroy_timer(self, timer: Timer) -> bool:
        """Destroy a timer of this node; False if it was not one of its own."""
        if timer in self._timers:
            self._timers.remove(timer)
            timer.destroy()
            return True
        return False

    def destroy_rate(self, rate: Rate) -> bool:
        """Destroy a rate made by create_rate (nothing to release)."""
        return True

    def destroy_node(self) -> None:
        """Destroy the node and all its entities; it leaves the graph. A second call does
        nothing.
        """
        if not self._custody.alive:
            return
        self._custody.alive = False
        if self.executor is not None:
            self.executor.remove_node(self)
        for timer in self._timers:
            timer.destroy()
        self._timers.clear()
        self._custody.entities.clear()
        self._bus.destroy_node()

    @property
    def publishers(self) -> list[Publisher]:
        """The node's publishers."""
        return [e for e in self._custody.entities if isinstance(e, Publisher)]

    @property
    def subscriptions(self) -> list[Subscription]:
        """The node's subscriptions."""
        return [e for e in self._custody.entities if isinstance(e, Subscription)]

    @property
    def timers(self) -> list[Timer]:
        """The node's timers."""
        return list(self._timers)

    @property
    def clients(self) -> list[Client]:
        """The node's service clients."""
        return [e for e in self._custody.entities if isinstance(e, Client)]

    @property
    def services(self) -> list[Service]:
        """The node's services."""
        return [e for e in self._custody.entities if isinstance(e, Service)]

    # --- the graph --------------------------------------------------------------------------
    def _entities_on_graph(self) -> list[keys.Entity]:
        self._custody.check_alive()
        return graph.entities(self._bus.graph_session(), 0.5)

    def count_publishers(self, topic_name: str) -> int:
        """How many publishers the graph has on `topic_name` (resolved)."""
        topic = self._bus.resolve(topic_name)
        return sum(1 for e in self._entities_on_graph()
                   if e.kind == keys.PUBLISHER and e.topic == topic)

    def count_subscribers(self, topic_name: str) -> int:
        """How many subscriptions the graph has on `topic_name` (resolved)."""
        topic = self._bus.resolve(topic_name)
        return sum(1 for e in self._entities_on_graph()
                   if e.kind == keys.SUBSCRIPTION and e.topic == topic)

    def count_services(self, service_name: str) -> int:
        """How many servers the graph has for `service_name` (resolved)."""
        name = self._bus.resolve(service_name, "service name")
        return sum(1 for e in self._entities_on_graph()
                   if e.kind == keys.SERVICE and e.topic == name)

    def count_clients(self, service_name: str) -> int:
        """How many clients the graph has of `service_name` (resolved)."""
        name = self._bus.resolve(service_name, "service name")
        return sum(1 for e in self._entities_on_graph()
                   if e.kind == keys.CLIENT and e.topic == name)

    def _names_and_types(self, kinds: tuple[str, ...]) -> list[tuple[str, list[str]]]:
        table: dict[str, set[str]] = {}
        for entity in self._entities_on_graph():
            if entity.kind in kinds:
                table.setdefault(entity.topic, set()).add(entity.type_name)
        return sorted((name, sorted(types)) for name, types in table.items())

    def get_topic_names_and_types(self, no_demangle: bool = False
                                  ) -> list[tuple[str, list[str]]]:
        """Every topic of the graph with its types: [(name, [type, …])]."""
        return self._names_and_types((keys.PUBLISHER, keys.SUBSCRIPTION))

    def get_service_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Every service of the graph with its types: [(name, [type, …])]."""
        return self._names_and_types((keys.SERVICE,))

    def _by_node(self, kinds: tuple[str, ...], node_name: str, node_namespace: str
                 ) -> list[tuple[str, list[str]]]:
        found = self._entities_on_graph()
        fqn = f"{(node_namespace or '/').rstrip('/')}/{node_name}"
        if not any(e.kind == keys.NODE and e.node_fqn == fqn for e in found):
            raise NodeNameNonExistentError(f"cannot find node '{fqn}'")
        table: dict[str, set[str]] = {}
        for entity in found:
            if entity.kind in kinds and entity.node_fqn == fqn:
                table.setdefault(entity.topic, set()).add(entity.type_name)
        return sorted((name, sorted(types)) for name, types in table.items())

    def get_publisher_names_and_types_by_node(self, node_name: str, node_namespace: str,
                                              no_demangle: bool = False
                                              ) -> list[tuple[str, list[str]]]:
        """The topics a node publishes, with their types (NodeNameNonExistentError if the
        node is not on the graph)."""
        return self._by_node((keys.PUBLISHER,), node_name, node_namespace)

    def get_subscriber_names_and_types_by_node(self, node_name: str, node_namespace: str,
                                               no_demangle: bool = False
                                               ) -> list[tuple[str, list[str]]]:
        """The topics a node subscribes to, with their types."""
        return self._by_node((keys.SUBSCRIPTION,), node_name, node_namespace)

    def get_service_names_and_types_by_node(self, node_name: str, node_namespace: str
                                            ) -> list[tuple[str, list[str]]]:
        """The services a node serves, with their types."""
        return self._by_node((keys.SERVICE,), node_name, node_namespace)

    def get_client_names_and_types_by_node(self, node_name: str, node_namespace: str
                                           ) -> list[tuple[str, list[str]]]:
        """The services a node is a client of, with their types."""
        return self._by_node((keys.CLIENT,), node_name, node_namespace)

    def get_node_names(self) -> list[str]:
        """The names of the graph's nodes."""
        return [e.node for e in self._entities_on_graph() if e.kind == keys.NODE]

    def get_node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """(name, namespace) of each node of the graph."""
        return [(e.node, e.namespace or "/") for e in self._entities_on_graph()
                if e.kind == keys.NODE]

    def wait_for_node(self, fully_qualified_node_name: str, timeout: float) -> bool:
        """Wait until a node of that fully qualified name is on the graph.

        :param fully_qualified_node_name: `/ns/name`.
        :param timeout: seconds to wait.
        :return: whether it came.
        """
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if any(f"{ns.rstrip('/')}/{n}" == fully_qualified_node_name
                   for n, ns in self.get_node_names_and_namespaces()):
                return True
            time.sleep(0.1)
        return False


def _time_source(node: Node, clock: ROSClock) -> TimeSource:
    """What makes the node's clock follow its /clock once jump callbacks are asked of it."""
    source = TimeSource(node=node)
    source.attach_clock(clock)
    return source


def _invalid_name(node_name: str, namespace: str, text: str) -> Exception:
    """rclpy's exception for a node name or namespace the bus refused (`text` says why)."""
    if "namespace" in text:
        full = namespace if namespace.startswith("/") else "/" + namespace
        fault = name_rules.full_topic_name(full, "namespace") or (text, 0)
        return InvalidNamespaceException(namespace, *fault)
    return InvalidNodeNameException(node_name, *(name_rules.node_name(node_name) or (text, 0)))


def __getattr__(name: str) -> Any:
    if name in _ON_USE:
        import importlib

        return getattr(importlib.import_module(_ON_USE[name]), name)
    raise AttributeError(f"module 'rclpy.node' has no attribute '{name}'")
