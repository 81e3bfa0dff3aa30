"""rclpy.node.Node over launcher's bus node: same names, same argument order and defaults.

Each Node owns one launcher bus node (its Zenoh session, graph tokens and parameter
services). Its entities' callbacks go on the node's queue; the executor it is spun by runs
them (see executors.py). Parameters follow rclpy: declared before use unless
`allow_undeclared_parameters`, overrides from `--ros-args -p` and params files win over
defaults, `add_on_set_parameters_callback` may refuse a change.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable, Sequence
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
    is_custom,
)
from rclpy.client import Client
from rclpy.clock import Clock, ROSClock  # noqa: F401
from rclpy.constants import S_TO_NS
from rclpy.context import Context  # noqa: F401
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
from rclpy.parameter import PARAMETER_SEPARATOR_STRING, Parameter  # noqa: F401
from rclpy.publisher import Publisher
from rclpy.qos import QoSProfile, qos_profile_services_default, to_launcher
from rclpy.service import Service
from rclpy.service_introspection import (
    REQUEST_RECEIVED,
    RESPONSE_SENT,
    Introspection,
)
from rclpy.subscription import ContentFilterOptions, MessageInfo, Subscription  # noqa: F401
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
# What rclpy's module offers from modules that import this one, or that a node needs only
# when asked: looked up at first use.
_ON_USE = {"Executor": "rclpy.executors", "LoggingService": "rclpy.logging_service",
           "ParameterService": "rclpy.parameter_service", "TimeSource": "rclpy.time_source",
           "TypeDescriptionService": "rclpy.type_description_service",
           "QoSOverridingOptions": "rclpy.qos_overriding_options"}


class NodeNameNonExistentError(RuntimeError):
    """Raised when a graph query names a node that is not on the graph."""

EMPTY_AFTER_PRE_SET = ("parameter list cannot be empty, this might be due to "
                       "pre_set_parameters_callback modifying the original parameters list.")


class Node:
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
            import sys

            given = self._context.args
            argv += list(sys.argv[1:] if given is None else given[1:])
        argv += list(cli_args or [])
        try:
            self._bus = BusNode(node_name, namespace=namespace or "", argv=argv,
                                parameter_services=start_parameter_services)
        except LaunchError as exc:
            raise _invalid_name(node_name, namespace or "", str(exc)) from None
        self._bus.owner = self
        self._host = self._bus.host
        self._host.ring_with(self._context.bell)  # its work wakes whichever executor spins it
        self._destroyed = False
        self.executor: Any = None
        self._timers: list[Timer] = []
        self._entities: list[Any] = []
        self.default_callback_group = MutuallyExclusiveCallbackGroup()
        self._callback_groups = [self.default_callback_group]
        self._logger = RcutilsLogger(
            f"{self._bus.namespace.strip('/').replace('/', '.')}.{self._bus.name}"
            if self._bus.namespace.strip("/") else self._bus.name)
        self._allow_undeclared = allow_undeclared_parameters
        self._overrides: dict[str, Any] = self._bus.parameters
        for parameter in parameter_overrides or []:
            self._overrides[parameter.name] = parameter.value
        self._declared: dict[str, Parameter] = {}
        self._descriptors: dict[str, Any] = {}
        self._set_callbacks: list[Callable[[list[Parameter]], Any]] = []
        self._pre_set_callbacks: list[Callable[[list[Parameter]], Any]] = []
        self._post_set_callbacks: list[Callable[[list[Parameter]], None]] = []
        self._pending_post: list[Parameter] | None = None
        self._bus.params.drop_all()  # what is declared, as rclpy lists it
        self._declare_now("use_sim_time", self._overrides.get("use_sim_time", False))
        if automatically_declare_parameters_from_overrides:
            for name, value in self._overrides.items():
                if name not in self._declared:
                    self._declare_now(name, value)
        self._bus.add_on_set_parameters_callback(self._on_bus_set)
        self._bus.params.gate, self._bus.params.describer = self._gate, self._describe_for_bus
        self._clock = ROSClock(self._bus.get_clock(), node=self)
        self._context.track_node(self)
        self._events: Any = None  # ParameterEvents, made at the first change after start
        self._started = True
        if enable_logger_service:
            from rclpy.logging_service import LoggingService  # only when asked

            LoggingService(self)

    # --- identity ---------------------------------------------------------------------------
    @property
    def context(self) -> Any:
        """The context the node belongs to (rclpy.init's, unless one was given)."""
        return self._context

    @property
    def handle(self) -> Any:
        """The launcher bus node under this node: its graph tokens, entities and services."""
        return self._bus

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
        return list(self._callback_groups)

    def add_waitable(self, waitable: Any) -> None:
        """Waitables are not supported: raises NotImplementedError."""
        raise NotImplementedError("waitables are not supported by launcher's rclpy")

    def _host_or_none(self) -> Any:
        return None if self._destroyed else self._host

    def _check_alive(self) -> None:
        if self._destroyed:
            from rclpy.exceptions import InvalidHandle

            raise InvalidHandle("cannot use Destroyable because destruction was requested")

    def _grouped(self, group: CallbackGroup | None, callback: Callable[..., Any],
                 entity: Callable[[], Any] = lambda: None) -> Callable[..., Any]:
        """The callback as its group runs it: under the group's lock if mutually exclusive;
        a group of the program's own (rclpy's CallbackGroup subclassed) is asked, as rclpy's
        executor asks it, beginning_execution(entity) before (False: it does not run) and
        told ending_execution(entity) after; its can_execute holds a timer back
        (Executor._next_work)."""
        group = group or self.default_callback_group
        if group not in self._callback_groups:
            self._callback_groups.append(group)
        if isinstance(group, MutuallyExclusiveCallbackGroup):
            return functools.partial(group.run, callback)
        if is_custom(group):
            def asked(*args: Any) -> Any:
                who = entity()
                if not group.beginning_execution(who):
                    return None
                try:
                    return callback(*args)
                finally:
                    group.ending_execution(who)
            return asked
        return callback

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
        self._check_alive()
        if qos_overriding_options is not None:
            qos_profile = self._overridden(qos_profile, "publisher", topic,
                                           qos_overriding_options)
        qos = to_launcher(qos_profile)
        bus = self._bus.create_publisher(rosidl.type_name_of(msg_type), topic, qos)
        publisher = publisher_class(bus, msg_type, topic, qos_profile, event_callbacks)
        self._entities.append(publisher)
        self._watch_matches(event_callbacks, bus.topic, keys.SUBSCRIPTION, callback_group,
                            publisher)
        return publisher

    def _overridden(self, qos_profile: QoSProfile | int, kind: str, topic: str,
                    options: Any) -> QoSProfile:
        """The QoS with the policies `options` names taken from their parameters."""
        from rclpy.qos_overriding_options import declare_qos_parameters  # only when asked

        if not isinstance(qos_profile, QoSProfile):
            qos_profile = QoSProfile(depth=int(qos_profile))
        return declare_qos_parameters(kind, self, self.resolve_topic_name(topic), qos_profile,
                                      options)

    def _watch_matches(self, event_callbacks: Any, topic: str, kind: str, group: Any,
                       entity: Any) -> None:
        """A matched-event callback, if given: told as the other side comes and goes."""
        matched = getattr(event_callbacks, "matched", None)
        if matched is None:
            return
        from rclpy.matched import (
            MatchWatcher,
            QoSPublisherMatchedInfo,
            QoSSubscriptionMatchedInfo,
        )

        info = QoSPublisherMatchedInfo if kind == keys.SUBSCRIPTION else \
            QoSSubscriptionMatchedInfo
        watcher = MatchWatcher(self, topic, kind, self._grouped(group, matched), info)
        destroy = entity.destroy

        def destroy_both() -> None:
            watcher.destroy()
            destroy()
        entity.destroy = destroy_both

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
        self._check_alive()
        if qos_overriding_options is not None:
            qos_profile = self._overridden(qos_profile, "subscription", topic,
                                           qos_overriding_options)
        type_name = rosidl.type_name_of(msg_type)
        made: list[Any] = []
        run = self._grouped(callback_group, callback, lambda: made[0] if made else None)
        if not raw:
            rosidl.message_class(type_name)  # made now, not on the first message
        bus = self._bus.create_subscription(type_name, topic, run, to_launcher(qos_profile),
                                            raw=raw, make=rosidl.make)
        subscription = Subscription(bus, msg_type, topic, callback, callback_group,
                                    qos_profile, raw, event_callbacks)
        made.append(subscription)
        self._entities.append(subscription)
        self._watch_matches(event_callbacks, bus.topic, keys.PUBLISHER, callback_group,
                            subscription)
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
        self._check_alive()
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
                                       self._grouped(callback_group, answer),
                                       make=rosidl.make, new_response=srv_type.Response)
        service = Service(bus, srv_type, srv_name, callback, callback_group, qos_profile)
        service._introspection = introspection
        self._entities.append(service)
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
        self._check_alive()
        bus = self._bus.create_client(rosidl.type_name_of(srv_type), srv_name,
                                      make=rosidl.make)
        rosidl.service_class(rosidl.type_name_of(srv_type))
        client = Client(self._context, bus, srv_type, srv_name, qos_profile, callback_group,
                        node=self)
        self._entities.append(client)
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
        self._check_alive()
        if timer_period_sec <= 0:
            raise ValueError(f"timer period must be > 0, got {timer_period_sec}")
        timer = Timer(callback, callback_group, int(timer_period_sec * 1e9), clock or
                      self._clock, context=self._context, autostart=autostart)
        bind_timer(timer, self._grouped(callback_group, callback, lambda: timer))
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
        guard = GuardCondition(callback, callback_group, self._context, host=self._host,
                               run=self._grouped(callback_group, callback))
        self._entities.append(guard)
        return guard

    # --- destroying -------------------------------------------------------------------------
    def _destroy_entity(self, entity: Any) -> bool:
        if entity in self._entities:
            self._entities.remove(entity)
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
        if self._destroyed:
            return
        self._destroyed = True
        if self.executor is not None:
            self.executor.remove_node(self)
        for timer in self._timers:
            timer.destroy()
        self._timers.clear()
        self._entities.clear()
        self._bus.destroy_node()

    @property
    def publishers(self) -> list[Publisher]:
        """The node's publishers."""
        return [e for e in self._entities if isinstance(e, Publisher)]

    @property
    def subscriptions(self) -> list[Subscription]:
        """The node's subscriptions."""
        return [e for e in self._entities if isinstance(e, Subscription)]

    @property
    def timers(self) -> list[Timer]:
        """The node's timers."""
        return list(self._timers)

    @property
    def clients(self) -> list[Client]:
        """The node's service clients."""
        return [e for e in self._entities if isinstance(e, Client)]

    @property
    def services(self) -> list[Service]:
        """The node's services."""
        return [e for e in self._entities if isinstance(e, Service)]

    # --- the graph --------------------------------------------------------------------------
    def _entities_on_graph(self) -> list[keys.Entity]:
        self._check_alive()
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

    # --- parameters -------------------------------------------------------------------------
    def _declare_now(self, name: str, value: Any) -> Parameter:
        parameter = Parameter(name, value=_plain(value))
        self._declared[name] = parameter
        self._bus.params.keep(name, parameter.value)
        return parameter

    def declare_parameter(self, name: str, value: Any = None, descriptor: Any = None,
                          ignore_override: bool = False) -> Parameter:
        """Declare a parameter: an override from the command line or a params file wins
        over `value`.

        :param name: the parameter's name.
        :param value: its default (or a Parameter.Type, for a parameter with no default).
        :param descriptor: a ParameterDescriptor (its type, read_only, ranges, description).
        :param ignore_override: take `value` even when an override was given.
        :return: the declared Parameter.
        """
        if isinstance(value, Parameter.Type):  # declare_parameter(name, Parameter.Type.X)
            value = None
        if name in self._declared:
            raise ParameterAlreadyDeclaredException([name])
        if not name:
            from rclpy.exceptions import InvalidParameterException

            raise InvalidParameterException(name)
        chosen = value if ignore_override or name not in self._overrides else \
            self._overrides[name]
        if value is not None and chosen is not None and not ignore_override and \
                name in self._overrides and _kind(value) != _kind(chosen) and \
                not (descriptor is not None and getattr(descriptor, "dynamic_typing", False)):
            raise InvalidParameterTypeException(Parameter(name, value=_plain(chosen)),
                                                Parameter(name, value=_plain(value)).type_.name)
        if descriptor is not None:
            self._descriptors[name] = descriptor
        declared = self._declare_now(name, chosen)
        self._announce(new=[declared])
        return declared

    def declare_parameters(self, namespace: str, parameters: Sequence[Any],
                           ignore_override: bool = False) -> list[Parameter]:
        """Declare several parameters under `namespace` (each (name, value[, descriptor])).

        :return: the declared Parameters, in order.
        """
        declared = []
        for entry in parameters:
            name, *rest = entry if isinstance(entry, tuple) else (entry,)
            full = f"{namespace}.{name}" if namespace else name
            declared.append(self.declare_parameter(full, *rest[:2],
                                                   ignore_override=ignore_override))
        return declared

    def undeclare_parameter(self, name: str) -> None:
        """Undeclare a parameter (ParameterNotDeclaredException if it was not declared)."""
        if name not in self._declared:
            raise ParameterNotDeclaredException(name)
        self._announce(deleted=[self._declared.pop(name)])
        self._bus.params.drop(name)

    def has_parameter(self, name: str) -> bool:
        """Whether the parameter is declared."""
        return name in self._declared

    def get_parameter(self, name: str) -> Parameter:
        """The declared parameter (ParameterNotDeclaredException if it is not, unless the
        node allows undeclared parameters).
        """
        if name in self._declared:
            return self._declared[name]
        if self._allow_undeclared:
            return Parameter(name, Parameter.Type.NOT_SET, None)
        raise ParameterNotDeclaredException(name)

    def get_parameter_or(self, name: str, alternative_value: Parameter | None = None
                         ) -> Parameter:
        """The parameter, or `alternative_value` when it is not declared."""
        if alternative_value is None:
            alternative_value = Parameter(name, Parameter.Type.NOT_SET)
        return self._declared.get(name, alternative_value)

    def get_parameters(self, names: list[str]) -> list[Parameter]:
        """The parameters of `names`, in order (see get_parameter)."""
        return [self.get_parameter(name) for name in names]

    def get_parameters_by_prefix(self, prefix: str) -> dict[str, Parameter]:
        """The parameters under `prefix.`, by their names after it."""
        start = f"{prefix}." if prefix else ""
        return {name[len(start):]: p for name, p in self._declared.items()
                if name.startswith(start)}

    @property
    def parameters(self) -> dict[str, Parameter]:
        """The declared parameters by name."""
        return dict(self._declared)

    def describe_parameter(self, name: str) -> Any:
        """The parameter's ParameterDescriptor (its declared one, else its name and type)."""
        from rcl_interfaces.msg import ParameterDescriptor

        if name not in self._declared:
            raise ParameterNotDeclaredException(name)
        return self._descriptors.get(name) or ParameterDescriptor(
            name=name, type=self._declared[name].type_.value)

    def add_on_set_parameters_callback(self, callback: Callable[[list[Parameter]], Any]
                                       ) -> Callable[[list[Parameter]], Any]:
        """Add a callback asked before parameters are set: it returns a
        SetParametersResult, and `successful=False` refuses the change.

        :return: the callback (to remove it later).
        """
        self._set_callbacks.insert(0, callback)
        return callback

    def remove_on_set_parameters_callback(self, callback: Any) -> None:
        """Remove a callback added by add_on_set_parameters_callback."""
        self._set_callbacks.remove(callback)

    def set_parameters(self, parameter_list: list[Parameter]) -> list[Any]:
        """Set parameters one at a time: a SetParametersResult for each."""
        return [self.set_parameters_atomically([p]) for p in parameter_list]

    def set_parameters_atomically(self, parameter_list: list[Parameter]) -> Any:
        """Set parameters all together or none: one SetParametersResult."""
        from rcl_interfaces.msg import SetParametersResult

        parameter_list = self._pre_set(list(parameter_list))
        if not parameter_list:
            return SetParametersResult(successful=False, reason=EMPTY_AFTER_PRE_SET)
        for parameter in parameter_list:
            if parameter.name not in self._declared and not self._allow_undeclared:
                raise ParameterNotDeclaredException(parameter.name)
        for callback in self._set_callbacks:
            result = callback(list(parameter_list))
            if result is not None and not result.successful:
                return result
        known = set(self._declared)
        for parameter in parameter_list:
            self._declared[parameter.name] = parameter
            self._bus.params.keep(parameter.name, parameter.value)
        self._announce(new=[p for p in parameter_list if p.name not in known],
                       changed=[p for p in parameter_list if p.name in known])
        self._post_set(parameter_list)
        return SetParametersResult(successful=True)

    # --- rclpy's pre-set (may change the list) and post-set (told what was set) callbacks ---
    def add_pre_set_parameters_callback(self, callback: Callable[[list[Parameter]], Any]
                                        ) -> Callable[[list[Parameter]], Any]:
        """Add a callback that may change the list of parameters about to
        be set (it returns the list to set).

        :return: the callback.
        """
        self._pre_set_callbacks.insert(0, callback)
        return callback

    def remove_pre_set_parameters_callback(self, callback: Any) -> None:
        """Remove a callback added by add_pre_set_parameters_callback."""
        self._pre_set_callbacks.remove(callback)

    def add_post_set_parameters_callback(self, callback: Callable[[list[Parameter]], None]
                                         ) -> Callable[[list[Parameter]], None]:
        """Add a callback told of the parameters once they are set.

        :return: the callback.
        """
        self._post_set_callbacks.insert(0, callback)
        return callback

    def remove_post_set_parameters_callback(self, callback: Any) -> None:
        """Remove a callback added by add_post_set_parameters_callback."""
        self._post_set_callbacks.remove(callback)

    def _pre_set(self, parameters: list[Parameter]) -> list[Parameter]:
        for callback in self._pre_set_callbacks:
            parameters = list(callback(list(parameters)) or [])
        return parameters

    def _post_set(self, parameters: list[Parameter]) -> None:
        for callback in self._post_set_callbacks:
            callback(list(parameters))

    def _gate(self, name: str, value: Any) -> str | None:
        """A set or delete asked from outside, checked as rclcpp/rclpy check it (the declared
        type, read_only, the set callbacks); the reason it is refused, or None."""
        descriptor = self._descriptors.get(name)
        if name not in self._declared and not self._allow_undeclared:
            return f"parameter '{name}' cannot be set because it was not declared"
        if descriptor is not None and descriptor.read_only:
            return f"parameter '{name}' cannot be set because it is read-only"
        dynamic = descriptor is not None and descriptor.dynamic_typing
        if value is None:
            if name in self._declared and not dynamic and not self._allow_undeclared:
                return "cannot undeclare a statically typed parameter"
            gone = self._declared.pop(name, None)
            self._announce(deleted=[gone] if gone is not None else [])
            return None
        parameters = self._pre_set([Parameter(name, value=_plain(value))])
        if not parameters:
            return EMPTY_AFTER_PRE_SET
        for parameter in parameters:
            old = self._declared.get(parameter.name)
            described = self._descriptors.get(parameter.name)
            loose = described is not None and described.dynamic_typing
            if parameter.name not in self._declared and not self._allow_undeclared:
                return (f"parameter '{parameter.name}' cannot be set because it was not "
                        "declared")
            if old is not None and old.type_ != Parameter.Type.NOT_SET and not loose and \
                    old.type_ != parameter.type_:
                return (f"Wrong parameter type, parameter {{{parameter.name}}} is of type "
                        f"{{{old.type_.name.lower()}}}, setting it to "
                        f"{{{parameter.type_.name.lower()}}} is not allowed.")
        for callback in self._set_callbacks:
            result = callback(list(parameters))
            if result is not None and not result.successful:
                return result.reason or "refused by the node's parameter callback"
        self._announce(new=[p for p in parameters if p.name not in self._declared],
                       changed=[p for p in parameters if p.name in self._declared])
        for parameter in parameters:
            self._declared[parameter.name] = parameter
            if parameter.name != name:  # one a pre-set callback added: set here
                self._bus.params.keep(parameter.name, parameter.value)
        self._pending_post = parameters
        return None

    def _announce(self, **parameters: list[Parameter]) -> None:
        """A change after start, on /parameter_events (parameter_events.py)."""
        if not getattr(self, "_started", False) or not any(parameters.values()):
            return
        if self._events is None:
            from rclpy.parameter_events import ParameterEvents  # at the first change

            self._events = ParameterEvents(self)
        self._events.announce(**parameters)

    def _describe_for_bus(self, name: str) -> dict[str, Any]:
        """The descriptor as plain fields, with its name and the declared type filled in
        (a ParameterDescriptor made in the node often has neither)."""
        if name not in self._declared:
            return {"name": name, "type": 0}
        fields = _fields(self.describe_parameter(name))
        fields["name"] = fields.get("name") or name
        fields["type"] = fields.get("type") or self._declared[name].type_.value
        return fields

    def _on_bus_set(self, name: str, value: Any) -> None:
        """`launcher param set` (or ros2 param) changed one: the callbacks hear of it."""
        parameter = Parameter(name, value=_plain(value))
        pending, self._pending_post = self._pending_post, None
        if pending is not None and any(p.name == name for p in pending):
            self._post_set(pending)  # (gated: validated and stored already)
            return
        if self._declared.get(name) == parameter:
            return
        self._announce(new=[] if name in self._declared else [parameter],
                       changed=[parameter] if name in self._declared else [])
        self._declared[name] = parameter
        for callback in self._set_callbacks:
            callback([parameter])


def _fields(message: Any) -> Any:
    """A message of rclpy's classes as plain data (dicts and lists)."""
    if hasattr(message, "get_fields_and_field_types"):
        return {f: _fields(getattr(message, f)) for f in message.get_fields_and_field_types()}
    if hasattr(message, "tolist"):
        return message.tolist()
    if isinstance(message, list | tuple):
        return [_fields(m) for m in message]
    return message


def _plain(value: Any) -> Any:
    return list(value) if isinstance(value, tuple) else value


def _kind(value: Any) -> Any:
    try:
        return Parameter.Type.from_parameter_value(_plain(value))
    except TypeError:
        return None


# --- what the rest of this rclpy (its executors, clients, action servers and clients) asks
# of a node, in one place: the Node class keeps rclpy's own surface ------------------------
def _invalid_name(node_name: str, namespace: str, text: str) -> Exception:
    """rclpy's exception for a node name or namespace the bus refused (`text` says why)."""
    if "namespace" in text:
        full = namespace if namespace.startswith("/") else "/" + namespace
        fault = name_rules.full_topic_name(full, "namespace") or (text, 0)
        return InvalidNamespaceException(namespace, *fault)
    return InvalidNodeNameException(node_name, *(name_rules.node_name(node_name) or (text, 0)))


def check_alive(node: Node) -> None:
    """rclpy's InvalidHandle once the node is destroyed."""
    node._check_alive()


def live_host(node: Node) -> Any:
    """The bus host that queues the node's work; None once the node is destroyed."""
    return node._host_or_none()


def caught_up(node: Node) -> None:
    """The executor has nothing left to do for the node (a sim in lockstep is told so)."""
    if node._host_or_none() is not None:
        node._bus.get_clock().caught_up()


def grouped(node: Node, group: CallbackGroup | None, callback: Callable[..., Any],
            entity: Callable[[], Any] = lambda: None) -> Callable[..., Any]:
    """`callback` as `group` (None: the node's default) runs it; see Node._grouped."""
    return node._grouped(group, callback, entity)


def adopt(node: Node, entity: Any) -> None:
    """An entity made outside the node (an action server or client) that it destroys with
    itself."""
    node._entities.append(entity)


def forget(node: Node, entity: Any) -> None:
    """The entity, destroyed by itself, is no longer the node's."""
    if entity in node._entities:
        node._entities.remove(entity)


def __getattr__(name: str) -> Any:
    if name in _ON_USE:
        import importlib

        return getattr(importlib.import_module(_ON_USE[name]), name)
    raise AttributeError(f"module 'rclpy.node' has no attribute '{name}'")
