"""rospy for launcher's graph: the API of ROS 1's Python client library over launcher's bus,
so ROS 1 node code (the course's publisher.py) runs unchanged where no real rospy is
installed (see launcher/compat/finder.py).

As in rospy, publishers and subscribers may be made before `init_node` (they join the graph
when it is called), callbacks run on a thread of their own while the main thread loops, and
Ctrl-C or SIGTERM shuts the node down: `is_shutdown()` turns true and sleeps raise
ROSInterruptException.

Parameters: `~name` is the node's own parameter (`_name:=value` on the command line sets
it); other names live on the graph's parameter server (bus/graph_parameters.py: the graph's
router hosts it, a ROS 1 launch fills it) when it answers, else on this node under their
resolved name; a name the server lacks is looked up in what the launch gave the node. Message
fields take whole numbers for floats, as ROS 1 did.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time as _time
from collections.abc import Callable
from typing import Any

from launcher.bus.qos import QoS
from launcher.compat import rosidl
from rospy.exceptions import (  # noqa: F401
    ROSException,
    ROSInitException,
    ROSInternalException,
    ROSInterruptException,
    ROSSerializationException,
    ROSTimeMovedBackwardsException,
    ServiceException,
    TransportException,
)
from rospy.rostime import Duration, Time  # noqa: F401

rosidl.lenient()

DEBUG, INFO, WARN, ERROR, FATAL = 1, 2, 4, 8, 16
_LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}


class _State:
    def __init__(self) -> None:
        self.node: Any = None
        self.name = "/unnamed"
        self.shutdown = threading.Event()
        self.reason = ""
        self.hooks: list[Callable[..., Any]] = []
        self.pending: list[Any] = []  # publishers/subscribers made before init_node
        self.level = INFO
        self.lock = threading.RLock()
        self.spinner: threading.Thread | None = None
        self.graph: Any = None  # the graph's parameter server's client, once asked


_state = _State()


def _need_node(what: str) -> Any:
    if _state.node is None:
        raise ROSInitException(f"{what}: the node is not initialized. Have you called "
                               "init_node()?")
    return _state.node


# --- the node ---------------------------------------------------------------------------------
def myargv(argv: list[str] | None = None) -> list[str]:
    """argv without ROS remapping arguments (`name:=value`)."""
    return [a for a in (sys.argv if argv is None else argv) if ":=" not in a]


def init_node(name: str, argv: list[str] | None = None, anonymous: bool = False,
              log_level: int | None = None, disable_rostime: bool = False,
              disable_rosout: bool = False, disable_signals: bool = False,
              xmlrpc_port: int = 0, tcpros_port: int = 0) -> None:
    from launcher.bus.node import Node
    from launcher.errors import LaunchError

    with _state.lock:
        if _state.node is not None:
            raise ROSException("rospy.init_node() has already been called with different "
                               "arguments: " + _state.name)
        if "/" in name.strip("/"):
            raise ValueError("namespaces are not allowed in node names")
        name = name.strip("/")
        if anonymous:
            name = f"{name}_{os.getpid()}_{int(_time.time() * 1000)}"
        given = sys.argv[1:] if argv is None else argv[1:]
        # ROS 1's `from:=to`, `__name:=`, `_param:=` (roslaunch's, rosrun's) and ROS 2's
        # `--ros-args …` are both read by the node (bus/ros_args.py)
        try:
            node = Node(name, argv=given)
        except LaunchError as exc:
            raise ROSInitException(str(exc)) from None
        if log_level is not None:
            _state.level = log_level
        _state.node = node
        _state.name = node.fully_qualified_name
        for entity in _state.pending:
            entity._attach(node)
        _state.pending.clear()
        _state.spinner = threading.Thread(target=_spin_callbacks, name="rospy-callbacks",
                                          daemon=True)
        _state.spinner.start()
    if not disable_signals and threading.current_thread() is threading.main_thread():
        for number in (signal.SIGINT, signal.SIGTERM):
            if signal.getsignal(number) in (signal.SIG_DFL, signal.default_int_handler):
                signal.signal(number, _on_signal)


def _spin_callbacks() -> None:
    """rospy runs callbacks on threads of their own: here, one thread for the node's."""
    node = _state.node
    while not _state.shutdown.is_set():
        try:
            node.spin_once(0.1)
        except Exception as exc:  # a callback's error is reported; the node goes on
            logerr(f"bad callback: {type(exc).__name__}: {exc}")


def _on_signal(number: int, frame: Any) -> None:
    _shut_down("signal-" + signal.Signals(number).name, destroy=False)


def get_name() -> str:
    return _state.name


get_caller_id = get_name


def get_namespace() -> str:
    node = _state.node
    return (node.namespace.rstrip("/") + "/") if node is not None else "/"


def get_node_uri() -> str:
    return ""


def resolve_name(name: str, caller_id: str | None = None) -> str:
    node = _need_node("resolve_name")
    return node.resolve(name)


def is_shutdown() -> bool:
    return _state.shutdown.is_set()


def core_is_shutdown() -> bool:
    return _state.shutdown.is_set()


def on_shutdown(hook: Callable[..., Any]) -> None:
    _state.hooks.append(hook)


def signal_shutdown(reason: str) -> None:
    _shut_down(reason, destroy=True)


def _shut_down(reason: str, destroy: bool) -> None:
    """In a signal handler the node is only told to stop; it is destroyed at exit (closing
    its session inside a handler could interrupt a put under way)."""
    with _state.lock:
        if _state.shutdown.is_set():
            return
        _state.reason = reason
        _state.shutdown.set()
    for hook in _state.hooks:
        try:
            hook()
        except TypeError:
            hook(reason)
    node = _state.node
    if node is not None:
        node.shutdown()
        if destroy:
            node.destroy_node()


def spin() -> None:
    _need_node("spin")
    try:
        while not _state.shutdown.wait(0.2):
            pass
    except KeyboardInterrupt:
        signal_shutdown("keyboard interrupt")


def sleep(duration: Any) -> None:
    seconds = duration.to_sec() if hasattr(duration, "to_sec") else float(duration)
    end = _time.monotonic() + seconds
    while True:
        if _state.shutdown.is_set():
            raise ROSInterruptException("ROS shutdown request")
        left = end - _time.monotonic()
        if left <= 0:
            return
        _state.shutdown.wait(min(left, 0.1))


class Rate:
    def __init__(self, hz: float, reset: bool = False) -> None:
        if hz <= 0:
            raise ROSException("rate must be > 0")
        self.sleep_dur = Duration.from_sec(1.0 / hz)
        self._period = 1.0 / hz
        self._next = _time.monotonic() + self._period

    def remaining(self) -> Duration:
        return Duration.from_sec(max(self._next - _time.monotonic(), 0.0))

    def sleep(self) -> None:
        left = self._next - _time.monotonic()
        if left > 0:
            sleep(left)
        elif _state.shutdown.is_set():
            raise ROSInterruptException("ROS shutdown request")
        self._next = max(self._next + self._period, _time.monotonic())


def get_rostime() -> Time:
    node = _need_node("time is not initialized")
    return Time(0, node.get_clock().now().nanoseconds)


def get_time() -> float:
    return get_rostime().to_sec()


# --- logging ----------------------------------------------------------------------------------
def _log(level: int, message: Any, *args: Any) -> None:
    if level < _state.level:
        return
    text = str(message) % args if args else str(message)
    stream = sys.stderr if level >= WARN else sys.stdout
    print(f"[{_LEVEL_NAMES[level]}] [{_time.time():.6f}]: {text}", file=stream, flush=True)


def logdebug(msg: Any, *args: Any, **kwargs: Any) -> None:
    _log(DEBUG, msg, *args)


def loginfo(msg: Any, *args: Any, **kwargs: Any) -> None:
    _log(INFO, msg, *args)


def logwarn(msg: Any, *args: Any, **kwargs: Any) -> None:
    _log(WARN, msg, *args)


def logerr(msg: Any, *args: Any, **kwargs: Any) -> None:
    _log(ERROR, msg, *args)


def logfatal(msg: Any, *args: Any, **kwargs: Any) -> None:
    _log(FATAL, msg, *args)


logout = loginfo
logerror = logerr
logwarning = logwarn
_throttled: dict[Any, float] = {}
_said: set[Any] = set()


def _throttle(level: int) -> Callable[..., None]:
    def log(period: float, msg: Any, *args: Any, **kwargs: Any) -> None:
        where = (sys._getframe(1).f_code, sys._getframe(1).f_lineno)
        now = _time.monotonic()
        if now - _throttled.get(where, -1e18) >= period:
            _throttled[where] = now
            _log(level, msg, *args)
    return log


def _once(level: int) -> Callable[..., None]:
    def log(msg: Any, *args: Any, **kwargs: Any) -> None:
        where = (sys._getframe(1).f_code, sys._getframe(1).f_lineno)
        if where not in _said:
            _said.add(where)
            _log(level, msg, *args)
    return log


logdebug_throttle, loginfo_throttle, logwarn_throttle, logerr_throttle, logfatal_throttle = (
    _throttle(level) for level in (DEBUG, INFO, WARN, ERROR, FATAL))
logdebug_once, loginfo_once, logwarn_once, logerr_once, logfatal_once = (
    _once(level) for level in (DEBUG, INFO, WARN, ERROR, FATAL))


# --- parameters -------------------------------------------------------------------------------
class _Unset:
    pass


_unspecified = _Unset()


def _parameter_key(name: str) -> str:
    """`~x` is the node's own `x`; other names are kept under their resolved name."""
    if name.startswith("~"):
        return name[1:].lstrip("/").replace("/", ".")
    node = _state.node
    if name.startswith("/"):
        return name
    return f"{get_namespace()}{name}" if node is not None else "/" + name


def _given(key: str, values: dict[str, Any]) -> str | None:
    """The node's parameter that holds `key`: the name itself, or, for a graph-wide name in
    the node's namespace, the name a launch gave the node for it (roslaunch's `<param>`
    outside a node reaches the node as its own `robot_description`)."""
    if key in values:
        return key
    space = get_namespace()
    if key.startswith(space):
        local = key[len(space):].replace("/", ".")
        if local in values:
            return local
    return None


def _server() -> Any:
    """The graph's parameter server's client, or None when the graph has none (then
    parameters stay on this node)."""
    if _state.graph is None:
        from launcher.bus.graph_parameters import GraphParameters

        _state.graph = GraphParameters(_state.node)
    return _state.graph if _state.graph.available() else None


def _on_server(call: Callable[[Any], Any]) -> Any:
    """`call(server)`, or _unspecified when no server answers (not there, or gone)."""
    from launcher.errors import LaunchError

    server = _server()
    if server is None:
        return _unspecified
    try:
        return call(server)
    except LaunchError:
        return _unspecified


def _local(key: str, values: dict[str, Any]) -> Any:
    found = _given(key, values)
    if found is not None:
        return values[found]
    prefix = key + ("." if not key.startswith("/") else "/")
    nested = {k[len(prefix):]: v for k, v in values.items() if k.startswith(prefix)}
    return nested if nested else _unspecified


def get_param(param_name: str, default: Any = _unspecified) -> Any:
    """`~x` from the node's own parameters; other names from the graph's parameter server
    (what any launch or node set there), then from what the launch gave this node."""
    from launcher.bus.graph_parameters import Missing

    node = _need_node("get_param")
    key = _parameter_key(param_name)
    if not param_name.startswith("~"):
        def ask(server: Any) -> Any:
            try:
                return server.get(key)
            except Missing:
                return _unspecified

        found = _on_server(ask)
        if found is not _unspecified:
            return found
    found = _local(key, node.parameters)
    if found is not _unspecified:
        return found
    if default is _unspecified:
        raise KeyError(param_name)
    return default


def get_param_cached(param_name: str, default: Any = _unspecified) -> Any:
    return get_param(param_name, default)


def set_param(param_name: str, param_value: Any) -> None:
    node = _need_node("set_param")
    key = _parameter_key(param_name)
    if param_name.startswith("~") or \
            _on_server(lambda server: server.set(key, param_value)) is _unspecified:
        node.set_parameter_value(key, param_value)


def has_param(param_name: str) -> bool:
    try:
        get_param(param_name)
    except KeyError:
        return False
    return True


def delete_param(param_name: str) -> None:
    """Deletes it (and what is below it) wherever it is; KeyError when it is nowhere."""
    from launcher.bus.graph_parameters import Missing

    node = _need_node("delete_param")
    key = _parameter_key(param_name)
    deleted = False
    if not param_name.startswith("~"):
        def delete(server: Any) -> bool:
            try:
                server.delete(key)
            except Missing:
                return False
            return True

        deleted = _on_server(delete) is True
    found = _given(key, node.parameters)
    if found is not None:
        node.drop_parameter(found)
    elif not deleted:
        raise KeyError(param_name)


def get_param_names() -> list[str]:
    node = _need_node("get_param_names")
    names = {k if k.startswith("/") else f"{_state.name}/{k}" for k in node.parameters}
    found = _on_server(lambda server: server.names())
    return sorted(names | set(found if found is not _unspecified else ()))


def search_param(param_name: str) -> str | None:
    key = _parameter_key(param_name)
    return key if has_param(param_name) else None


# --- topics -----------------------------------------------------------------------------------
def _build(data_class: Any, args: tuple, kwargs: dict) -> Any:
    if len(args) == 1 and not kwargs and isinstance(args[0], data_class):
        return args[0]
    return data_class(*args, **kwargs)


class _Endpoint:
    """What a Publisher and a Subscriber share: the type, the name, and joining the graph at
    `init_node` when made before it."""

    def __init__(self, name: str, data_class: Any, qos: QoS) -> None:
        if not isinstance(data_class, type) or not hasattr(data_class, "_TYPE"):
            raise ValueError(f"data_class [{data_class}] is not a message data class")
        self.data_class, self.type = data_class, rosidl.type_name_of(data_class)
        self._qos, self._given, self._bus = qos, name, None
        self.name = self.resolved_name = name

    def _join(self) -> None:
        with _state.lock:
            if _state.node is None:
                _state.pending.append(self)
            else:
                self._attach(_state.node)

    def _attach(self, node: Any) -> None:
        raise NotImplementedError

    def unregister(self) -> None:
        if self._bus is not None:
            self._bus.destroy()
            self._bus = None


class Publisher(_Endpoint):
    def __init__(self, name: str, data_class: Any, subscriber_listener: Any = None,
                 tcp_nodelay: bool = False, latch: bool = False, headers: Any = None,
                 queue_size: int | None = None) -> None:
        super().__init__(name, data_class, QoS(depth=1, transient_local=True) if latch else
                         QoS(depth=max(queue_size or 10, 1)))
        self._join()

    def _attach(self, node: Any) -> None:
        self._bus = node.create_publisher(self.type, self._given, self._qos)
        self.name = self.resolved_name = self._bus.topic

    def publish(self, *args: Any, **kwargs: Any) -> None:
        if self._bus is None:
            raise ROSException("ROS node has not been initialized yet. Please call "
                               "init_node() first")
        if _state.shutdown.is_set():
            raise ROSException("publish() to a closed topic")
        message = _build(self.data_class, args, kwargs)
        self._bus.publish(message)

    def get_num_connections(self) -> int:
        return 0 if self._bus is None else self._bus.get_subscription_count()


class Subscriber(_Endpoint):
    def __init__(self, name: str, data_class: Any, callback: Callable[..., Any] | None = None,
                 callback_args: Any = None, queue_size: int | None = None,
                 buff_size: int = 65536, tcp_nodelay: bool = False) -> None:
        super().__init__(name, data_class, QoS(depth=max(queue_size or 10, 1)))
        self.callback, self.callback_args = callback, callback_args
        self._callbacks: list[tuple[Callable[..., Any], Any]] = []
        if callback is not None:
            self._callbacks.append((callback, callback_args))
        self._join()

    def _attach(self, node: Any) -> None:
        type_name = self.type

        def deliver(converted: Any) -> None:
            for callback, extra in list(self._callbacks):
                if extra is None:
                    callback(converted)
                else:
                    callback(converted, extra)
        # latched publishers' last message reaches late subscribers, as in ROS 1
        qos = QoS(depth=self._qos.depth, transient_local=True)
        self._bus = node.create_subscription(type_name, self._given, deliver, qos,
                                             make=rosidl.make)
        self.name = self.resolved_name = self._bus.topic

    def get_num_connections(self) -> int:
        return 0


def wait_for_message(topic: str, topic_type: Any, timeout: float | None = None) -> Any:
    _need_node("wait_for_message")
    got: list[Any] = []
    arrived = threading.Event()

    def take(message: Any) -> None:
        if not got:
            got.append(message)
            arrived.set()
    subscriber = Subscriber(topic, topic_type, take)
    try:
        end = None if timeout is None else _time.monotonic() + timeout
        while not arrived.wait(0.1):
            if _state.shutdown.is_set():
                raise ROSInterruptException("rospy shutdown")
            if end is not None and _time.monotonic() >= end:
                raise ROSException(f"timeout exceeded while waiting for message on topic "
                                   f"{subscriber.name}")
        return got[0]
    finally:
        subscriber.unregister()


def get_published_topics(namespace: str = "/") -> list[list[str]]:
    from launcher.bus import graph, keys

    node = _need_node("get_published_topics")
    found: dict[str, str] = {}
    for entity in graph.entities(node.graph_session(), 0.5):
        if entity.kind == keys.PUBLISHER and entity.topic.startswith(namespace):
            package, _, short = entity.type_name.split("/")
            found[entity.topic] = f"{package}/{short}"
    return [[name, kind] for name, kind in sorted(found.items())]


# --- services ---------------------------------------------------------------------------------
def _response(service_class: Any, result: Any) -> Any:
    response_class = service_class.Response
    if isinstance(result, response_class):
        return result
    if result is None:
        raise ServiceException("service handler returned None")
    if isinstance(result, dict):
        return response_class(**result)
    if isinstance(result, list | tuple):
        return response_class(*result)
    return response_class(result)


class Service:
    def __init__(self, name: str, service_class: Any, handler: Callable[[Any], Any],
                 buff_size: int = 65536, error_handler: Any = None) -> None:
        self.service_class, self.handler = service_class, handler
        self.type = rosidl.type_name_of(service_class)
        node = _need_node("Service")

        def answer(request: Any, _given: Any) -> Any:
            return _response(service_class, handler(request))
        self._bus = node.create_service(self.type, name, answer, make=rosidl.make,
                                        new_response=service_class.Response)
        self.resolved_name = self._bus.name

    def shutdown(self, reason: str = "") -> None:
        self._bus.destroy()

    def spin(self) -> None:
        spin()


ServiceProxyError = ServiceException


class ServiceProxy:
    def __init__(self, name: str, service_class: Any, persistent: bool = False,
                 headers: Any = None) -> None:
        self.service_class = service_class
        self.request_class, self.response_class = service_class.Request, \
            service_class.Response
        self.type = rosidl.type_name_of(service_class)
        self.resolved_name = name
        self._given, self._bus = name, None

    def _client(self) -> Any:
        if self._bus is None:
            node = _need_node("ServiceProxy")
            self._bus = node.create_client(self.type, self._given, make=rosidl.make)
            self.resolved_name = self._bus.name
        return self._bus

    def wait_for_service(self, timeout: float | None = None) -> None:
        wait_for_service(self._given, timeout)

    def call(self, *args: Any, **kwargs: Any) -> Any:
        from launcher.errors import LaunchError

        request = _build(self.request_class, args, kwargs)
        client = self._client()
        try:
            return client.call(request, 30.0)
        except LaunchError as exc:
            raise ServiceException(f"service [{self.resolved_name}] call failed: {exc}"
                                   ) from None

    __call__ = call

    def close(self) -> None:
        if self._bus is not None:
            self._bus.destroy()
            self._bus = None


def wait_for_service(service: str, timeout: float | None = None) -> None:
    from launcher.bus import graph, keys

    node = _need_node("wait_for_service")
    name = node.resolve(service, "service name")
    end = None if timeout is None else _time.monotonic() + timeout
    while True:
        if any(e.kind == keys.SERVICE and e.topic == name
               for e in graph.entities(node.graph_session(), 0.5)):
            return
        if _state.shutdown.is_set():
            raise ROSInterruptException("rospy shutdown")
        if end is not None and _time.monotonic() >= end:
            raise ROSException(f"timeout exceeded while waiting for service {name}")
        _time.sleep(0.05)
