"""The node API: publishers, subscriptions, services, clients, timers, parameters.

Threading: Zenoh delivers samples and queries on its own threads; they only put work on the
node's queue. `spin()` / `spin_once()` run every callback (subscriptions, services, timers)
one at a time on the calling thread, like rclpy's single-threaded executor, so a slow
callback delays other callbacks but never the bus. Publishing and calling services are safe
from any thread.

Names follow ROS 2 (relative, absolute, `~`), with the `--ros-args` remaps applied. Messages
are CDR (rosbags); keys, liveliness tokens and attachments follow rmw_zenoh (see keys.py).
"""

from __future__ import annotations

import atexit
import contextlib
import itertools
import os
import queue
import sys
import threading
import time
from collections import deque
from collections.abc import Callable
from typing import Any

import zenoh

from launcher.bus import discovery, keys, names, ros_args
from launcher.bus.clock import Clock
from launcher.bus.qos import QoS, qos_of
from launcher.bus.services import Client, Service
from launcher.bus.session import NoRouter, open_session
from launcher.bus.types import registry
from launcher.errors import LaunchError

_node_ids = itertools.count()


class Logger:
    LEVELS = {"DEBUG": 10, "INFO": 20, "WARN": 30, "ERROR": 40, "FATAL": 50}

    def __init__(self, name: str, level: str = "INFO") -> None:
        self.name, self.threshold = name, self.LEVELS.get(level.upper(), 20)
        self._once: set[str] = set()

    def _log(self, level: str, message: str, once: bool = False) -> None:
        if self.LEVELS[level] < self.threshold or (once and message in self._once):
            return
        self._once.add(message)
        stream = sys.stderr if self.LEVELS[level] >= 30 else sys.stdout
        print(f"[{level}] [{time.time():.6f}] [{self.name}]: {message}", file=stream,
              flush=True)

    def debug(self, message: str, once: bool = False) -> None:
        self._log("DEBUG", message, once)

    def info(self, message: str, once: bool = False) -> None:
        self._log("INFO", message, once)

    def warning(self, message: str, once: bool = False) -> None:
        self._log("WARN", message, once)

    warn = warning

    def error(self, message: str, once: bool = False) -> None:
        self._log("ERROR", message, once)


class Parameter:
    def __init__(self, name: str, value: Any) -> None:
        self.name, self.value = name, value


class Publisher:
    def __init__(self, node: Node, type_name: str, topic: str, qos: QoS) -> None:
        types = registry()
        self.type_name = types.ensure(type_name)
        self.topic, self.qos, self._node = topic, qos, node
        key = keys.topic_key(keys.DOMAIN, topic, self.type_name, types.type_hash(self.type_name))
        # Reliable means "do not drop": block under congestion, as ROS 2 reliable QoS does.
        if qos.reliable:
            self._publisher = node.session.declare_publisher(
                key, reliability=zenoh.Reliability.RELIABLE,
                congestion_control=zenoh.CongestionControl.BLOCK)
        else:
            self._publisher = node.session.declare_publisher(
                key, reliability=zenoh.Reliability.BEST_EFFORT,
                congestion_control=zenoh.CongestionControl.DROP)
        self._sequence = itertools.count(1)
        self._gid = os.urandom(16)
        self._cache: deque[tuple[bytes, bytes]] = deque(maxlen=qos.depth)
        self._queryable = node.session.declare_queryable(key, self._replay) \
            if qos.transient_local else None
        self._token = node._announce(keys.PUBLISHER, topic, self.type_name, qos)
        # Kept current by Zenoh, so asking costs an attribute read (the sim asks every step).
        self._matching = self._publisher.matching_status.matching
        self._watchers: list[Callable[[bool], None]] = []
        self._closed = False
        self._listener = self._publisher.declare_matching_listener(self._on_matching)

    def _on_matching(self, status: Any) -> None:
        self._matching = status.matching
        for watcher in self._watchers:
            self._node._enqueue(watcher, status.matching)

    def watch_subscribers(self, callback: Callable[[bool], None]) -> None:
        """Call `callback(matching)` on the executor whenever subscribers come or all go
        (and once now); lazy bridges subscribe to their source only while someone listens."""
        self._watchers.append(callback)
        self._node._enqueue(callback, self._matching)

    def publish(self, message: Any) -> None:
        self.publish_raw(registry().serialize(message, self.type_name))

    def publish_raw(self, payload: bytes) -> None:
        """Publish a CDR payload as it is (bag play, bridges)."""
        attachment = keys.attachment(next(self._sequence), time.time_ns(), self._gid)
        if self._queryable is not None:
            self._cache.append((payload, attachment))
        try:
            self._publisher.put(payload, attachment=attachment)
        except zenoh.ZError:
            if not self._closed:  # a callback on Zenoh's thread may race destroy(): quiet
                raise

    def _replay(self, query: zenoh.Query) -> None:
        for payload, attachment in list(self._cache):
            query.reply(self._publisher.key_expr, payload, attachment=attachment)

    def get_subscription_count(self) -> int:
        """1 while any subscriber matches (Zenoh does not count them), else 0."""
        return 1 if self._matching else 0

    def destroy(self) -> None:
        if not self._node._forget(self):
            return
        self._closed = True
        for item in (self._listener, self._queryable, self._publisher, self._token):
            if item is not None:
                item.undeclare()


class Subscription:
    def __init__(self, node: Node, type_name: str, topic: str, callback: Callable[[Any], None],
                 qos: QoS, raw: bool = False, inline: bool = False,
                 remote_only: bool = False) -> None:
        types = registry()
        self.type_name = types.ensure(type_name)
        self.topic, self.qos, self._node, self._callback = topic, qos, node, callback
        self._raw, self._inline = raw, inline
        key = keys.topic_key(keys.DOMAIN, topic, self.type_name, types.type_hash(self.type_name))
        self._subscriber = node.session.declare_subscriber(
            key, self._on_sample,
            allowed_origin=zenoh.Locality.REMOTE if remote_only else zenoh.Locality.ANY)
        self._token = node._announce(keys.SUBSCRIPTION, topic, self.type_name, qos)
        self._warned = False
        if qos.transient_local:  # fetch what latched publishers hold
            for reply in node.session.get(key, timeout=node.timeout):
                if reply.ok is not None:
                    self._on_sample(reply.ok)

    def _on_sample(self, sample: zenoh.Sample) -> None:
        if self._inline:
            self._deliver(sample.payload.to_bytes())
        else:
            self._node._enqueue(self._deliver, sample.payload.to_bytes())

    def _deliver(self, payload: bytes) -> None:
        if self._raw:
            self._callback(payload)
            return
        try:
            message = registry().deserialize(payload, self.type_name)
        except Exception as exc:  # malformed payload: dropped, said once per topic
            if not self._warned:
                self._warned = True
                self._node.get_logger().warning(
                    f"dropped a malformed {self.type_name} message on {self.topic}: {exc}")
            return
        self._callback(message)

    def destroy(self) -> None:
        if not self._node._forget(self):
            return
        self._subscriber.undeclare()
        self._token.undeclare()


class Timer:
    def __init__(self, node: Node, period: float, callback: Callable[[], None]) -> None:
        self.period, self._callback, self._node = period, callback, node
        self.next = time.monotonic() + period
        self.cancelled = False

    def cancel(self) -> None:
        self.cancelled = True


class Rate:
    """Sleep so that a loop runs at `hz`, against a monotonic clock (no drift)."""

    def __init__(self, hz: float) -> None:
        self.period = 1.0 / hz
        self._next = time.monotonic() + self.period

    def sleep(self) -> None:
        delay = self._next - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        self._next = max(self._next + self.period, time.monotonic())


class Node:
    def __init__(self, name: str, *, namespace: str = "", argv: list[str] | None = None,
                 session: zenoh.Session | None = None, parameter_services: bool = True) -> None:
        parsed = ros_args.parse(sys.argv[1:] if argv is None else argv)
        self.name = names.check_node_name(parsed.node_name or name)
        self.namespace = names.check_namespace(parsed.namespace or namespace)
        self.remaps = parsed.remaps
        self.args = parsed.user_args
        self._logger = Logger(self.fully_qualified_name, parsed.log_level or "INFO")
        self._parameters: dict[str, Any] = {}
        for path in parsed.params_files:
            self._parameters.update(ros_args.load_params_file(path, self.name, self.namespace))
        self._parameters.update(parsed.parameters)
        self.session = session or open_session("peer", host_if_alone=True)
        self._graph_session: zenoh.Session | None = None
        self.timeout = 2.0
        self._node_id = next(_node_ids)
        self._entity_ids = itertools.count(1)
        self._queue: queue.SimpleQueue[tuple[Callable[..., Any], tuple]] = queue.SimpleQueue()
        self._timers: list[Timer] = []
        self._entities: list[Any] = []
        self._token = self.session.liveliness().declare_token(keys.liveliness_key(
            keys.DOMAIN, keys.Entity(str(self.session.zid()), self._node_id, 0, keys.NODE,
                                self.namespace, self.name)))
        self._stopped = threading.Event()
        self.interrupted = False  # Ctrl-C arrived during spin()
        self._destroyed = False
        # Zenoh runs callbacks on non-daemon threads, which the interpreter joins at exit
        # before atexit handlers run: a node never destroyed would hang its program. The
        # threading module's own exit hook (concurrent.futures uses it) runs before the join.
        register = getattr(threading, "_register_atexit", atexit.register)
        register(self.destroy_node)
        self._on_set: list[Callable[[str, Any], None]] = []
        if parameter_services:
            from launcher.bus.parameters import serve  # rcl_interfaces types: only here

            serve(self)
        self._clock = Clock(self, bool(self._parameters.get("use_sim_time", False)))

    # --- names ------------------------------------------------------------------------------
    @property
    def fully_qualified_name(self) -> str:
        return f"{self.namespace}/{self.name}"

    def resolve(self, name: str, what: str = "topic name") -> str:
        full = names.expand(name, self.name, self.namespace, what)
        return names.remap(full, self.remaps, self.name, self.namespace)

    def _announce(self, kind: str, topic: str, type_name: str, qos: QoS) -> Any:
        entity = keys.Entity(str(self.session.zid()), self._node_id, next(self._entity_ids),
                             kind, self.namespace, self.name, topic, type_name,
                             registry().type_hash(type_name), qos.key())
        return self.session.liveliness().declare_token(keys.liveliness_key(keys.DOMAIN, entity))

    # --- endpoints --------------------------------------------------------------------------
    def create_publisher(self, type_name: str, topic: str, qos: QoS | int = 10) -> Publisher:
        publisher = Publisher(self, type_name, self.resolve(topic), qos_of(qos))
        self._entities.append(publisher)
        return publisher

    def create_subscription(self, type_name: str, topic: str, callback: Callable[[Any], None],
                            qos: QoS | int = 10, raw: bool = False,
                            inline: bool = False, remote_only: bool = False) -> Subscription:
        """`raw=True` hands the callback the CDR bytes instead of a message. `inline=True`
        runs the callback on Zenoh's delivery thread instead of the executor: no hand-over
        between threads (it halves the CPU of a 1 kHz stream), but the callback must be
        thread-safe against the node's other callbacks and must not block. `remote_only=True`
        ignores what this process publishes (a two-way bridge must not hear itself)."""
        subscription = Subscription(self, type_name, self.resolve(topic), callback, qos_of(qos),
                                    raw, inline, remote_only)
        self._entities.append(subscription)
        return subscription

    def create_service(self, type_name: str, name: str,
                       callback: Callable[[Any, Any], Any]) -> Service:
        service = Service(self, type_name, self.resolve(name, "service name"), callback)
        self._entities.append(service)
        return service

    def create_client(self, type_name: str, name: str) -> Client:
        client = Client(self, type_name, self.resolve(name, "service name"))
        self._entities.append(client)
        return client

    def _announce_service(self, kind: str, name: str, type_name: str) -> Any:
        entity = keys.Entity(str(self.session.zid()), self._node_id, next(self._entity_ids),
                             kind, self.namespace, self.name, name, type_name,
                             registry().service_hash(type_name), QoS().key())
        return self.session.liveliness().declare_token(keys.liveliness_key(keys.DOMAIN, entity))

    def create_timer(self, period: float, callback: Callable[[], None]) -> Timer:
        if period <= 0:
            raise LaunchError(f"timer period must be > 0, got {period}")
        timer = Timer(self, period, callback)
        self._timers.append(timer)
        return timer

    def message(self, type_name: str, **fields: Any) -> Any:
        """A message of `type_name`; nested fields default to their zero values."""
        from launcher.bus.messages import build

        return build(type_name, fields)

    # --- parameters -------------------------------------------------------------------------
    def declare_parameter(self, name: str, default: Any = None) -> Parameter:
        self._parameters.setdefault(name, default)
        return Parameter(name, self._parameters[name])

    def get_parameter(self, name: str) -> Parameter:
        if name not in self._parameters:
            raise LaunchError(f"parameter '{name}' is not declared on {self.fully_qualified_name}")
        return Parameter(name, self._parameters[name])

    def has_parameter(self, name: str) -> bool:
        return name in self._parameters

    def set_parameters(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            self.set_parameter_value(parameter.name, parameter.value)

    def set_parameter_value(self, name: str, value: Any) -> None:
        """Set one parameter (also from `launcher param set`) and tell the listeners."""
        self._parameters[name] = value
        for listener in self._on_set:
            listener(name, value)

    def add_on_set_parameters_callback(self, callback: Callable[[str, Any], None]) -> None:
        self._on_set.append(callback)

    @property
    def parameters(self) -> dict[str, Any]:
        return dict(self._parameters)

    def get_logger(self) -> Logger:
        return self._logger

    def get_clock(self) -> Clock:
        return self._clock

    # --- executing --------------------------------------------------------------------------
    def _enqueue(self, callback: Callable[..., Any], *args: Any) -> None:
        self._queue.put((callback, args))

    def spin_once(self, timeout: float | None = None) -> bool:
        """Run one ready callback (or due timer), waiting up to `timeout`; True if one ran."""
        now = time.monotonic()
        due = [t for t in self._timers if not t.cancelled]
        if due:
            first = min(due, key=lambda t: t.next)
            if first.next <= now:
                first.next = max(first.next + first.period, now)
                first._callback()
                return True
            wait = first.next - now if timeout is None else min(timeout, first.next - now)
        else:
            wait = timeout
        try:
            callback, args = self._queue.get(timeout=wait)
        except queue.Empty:
            return False
        callback(*args)
        return True

    def spin(self, duration: float | None = None) -> None:
        """Run callbacks until Ctrl-C, `shutdown()`, or `duration` seconds.

        Ctrl-C ends the spin quietly (so `node.spin(); node.destroy_node()` is a whole
        program) and sets `interrupted`, for loops that spin in slices."""
        end = None if duration is None else time.monotonic() + duration
        try:
            while not self._stopped.is_set():
                remaining = None if end is None else end - time.monotonic()
                if remaining is not None and remaining <= 0:
                    return
                self.spin_once(0.1 if remaining is None else min(0.1, remaining))
        except KeyboardInterrupt:
            self.interrupted = True

    def _forget(self, entity: Any) -> bool:
        """Drop an entity being destroyed; False if it already was (destroy is idempotent)."""
        if entity in self._entities:
            self._entities.remove(entity)
            return True
        return False

    def shutdown(self) -> None:
        self._stopped.set()

    def graph_session(self) -> zenoh.Session:
        """The session to ask who is on the bus. A peer's liveliness query reaches only the
        peers it has links to, and with dozens of nodes starting at once some links come late
        or not at all (ten robots' `create`s never saw the sim); the router answers a client
        with every token. Opened at the first question; a node hosting its own bus, or on a
        config of the user's, asks through its own session."""
        if self._graph_session is None:
            self._graph_session = self.session
            if not os.environ.get(discovery.CONFIG_VARIABLE):
                with contextlib.suppress(NoRouter):
                    self._graph_session = open_session("client")
        return self._graph_session

    def destroy_node(self) -> None:
        """Undeclare everything and close the session; safe to call more than once."""
        if self._destroyed:
            return
        self._destroyed = True
        if self._graph_session not in (None, self.session):
            with contextlib.suppress(zenoh.ZError):
                self._graph_session.close()
        for entity in list(self._entities):
            # the session must close whatever happened to one entity
            with contextlib.suppress(zenoh.ZError):
                entity.destroy()
        self._token.undeclare()
        self.session.close()

