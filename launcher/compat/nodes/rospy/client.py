"""rospy.client: init_node and the node's names, spin, parameters, and waiting for a
message (rospy's own client module holds the same)."""

from __future__ import annotations

import os
import signal
import sys
import threading
import time as _time
from collections.abc import Callable
from typing import Any

from launcher.bus.subscription import FirstMessage
from rospy import names
from rospy.core import (  # noqa: F401 (rospy.client has them)
    DEBUG,
    ERROR,
    FATAL,
    INFO,
    WARN,
    add_client_shutdown_hook,
    logdebug,
    logerr,
    loginfo,
    logwarn,
    need_node,
    set_initialized,
    shut_down,
    signal_shutdown,
    state,
)
from rospy.exceptions import ROSException, ROSInitException, ROSInterruptException
from rospy.impl import log as _log
from rospy.names import get_namespace
from rospy.rostime import get_time, set_rostime_initialized
from rospy.service import Service  # noqa: F401 (rospy.client has it)
from rospy.topics import Subscriber, attach_pending

TIMEOUT_READY = 15.0  # seconds rospy waits for its node's servers to start


def myargv(argv: list[str] | None = None) -> list[str]:
    """argv without ROS remapping arguments (`name:=value`)."""
    return [a for a in (sys.argv if argv is None else argv) if ":=" not in a]


def load_command_line_node_params(argv: list[str]) -> dict[str, Any]:
    """{name: value} of the `_name:=value` private parameters in `argv` (values read as
    YAML); ROSInitException when one does not read."""
    import yaml

    params = {}
    try:
        for arg in argv:
            source, found, value = arg.partition(names.REMAP)
            source = source.strip()
            if found and len(source) > 1 and source[0] == "_" and source[1] != "_" and \
                    value.strip():
                params[source[1:]] = yaml.safe_load(value.strip())
    except yaml.YAMLError as exc:
        raise ROSInitException(f"invalid command-line parameters: {exc}") from None
    return params


def on_shutdown(h: Callable[[], Any]) -> None:
    """Call `h()` when the node shuts down, before it is taken down."""
    add_client_shutdown_hook(h)


def init_node(name: str, argv: list[str] | None = None, anonymous: bool = False,
              log_level: int | None = None, disable_rostime: bool = False,
              disable_rosout: bool = False, disable_signals: bool = False,
              xmlrpc_port: int = 0, tcpros_port: int = 0) -> None:
    """Join the graph as node `name` (once a process). Publishers and subscribers made
    before join it now; callbacks run on a thread of their own; Ctrl-C and SIGTERM shut the node
    down unless `disable_signals`.

    :param name: the node's name (no namespace: `__ns:=` gives one).
    :param argv: the command line to read remaps and `_param:=` values from (default sys.argv).
    :param anonymous: add the process id and time to the name, so that several can run.
    :param log_level: the lowest level printed (rospy.DEBUG … rospy.FATAL).
    """
    from launcher.bus.node import Node
    from launcher.errors import LaunchError

    with state.lock:
        if state.node is not None:
            raise ROSException("rospy.init_node() has already been called with different "
                               "arguments: " + state.name)
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
            _log.threshold[0] = log_level
        _log.clock[0] = get_time
        state.node = node
        state.name = node.fully_qualified_name
        if argv is not None:
            names.reload_mappings(argv)
        names.initialize_mappings(state.name)
        names.set_caller_id(state.name, node.resolve)
        set_initialized(True)
        set_rostime_initialized(True)
        attach_pending(node)
        state.spinner = threading.Thread(target=_spin_callbacks, name="rospy-callbacks",
                                         daemon=True)
        state.spinner.start()
    if not disable_signals and threading.current_thread() is threading.main_thread():
        for number in (signal.SIGINT, signal.SIGTERM):
            if signal.getsignal(number) in (signal.SIG_DFL, signal.default_int_handler):
                signal.signal(number, _on_signal)


def _spin_callbacks() -> None:
    """rospy runs callbacks on threads of their own: here, one thread for the node's."""
    node = state.node
    while not state.shutdown.is_set():
        try:
            node.spin_once(0.1)
        except Exception as exc:  # a callback's error is reported; the node goes on
            logerr(f"bad callback: {type(exc).__name__}: {exc}")


def _on_signal(number: int, frame: Any) -> None:
    shut_down("signal-" + signal.Signals(number).name, destroy=False)


def spin() -> None:
    """Block until the node shuts down (Ctrl-C, SIGTERM, signal_shutdown)."""
    need_node("spin")
    try:
        while not state.shutdown.wait(0.2):
            pass
    except KeyboardInterrupt:
        signal_shutdown("keyboard interrupt")


# --- parameters -------------------------------------------------------------------------------
class _Unset:
    pass


_unspecified = _Unset()


def _parameter_key(name: str) -> str:
    """`~x` is the node's own `x`; other names are kept under their resolved name."""
    if name.startswith("~"):
        return name[1:].lstrip("/").replace("/", ".")
    node = state.node
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
    if state.graph is None:
        from launcher.bus.graph_parameters import GraphParameters

        state.graph = GraphParameters(state.node)
    return state.graph if state.graph.available() else None


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

    node = need_node("get_param")
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
    """As get_param (launcher keeps no cache to go stale)."""
    return get_param(param_name, default)


def set_param(param_name: str, param_value: Any) -> None:
    """Set a parameter: `~x` on the node, other names on the graph's parameter server
    (on the node when the graph has none).
    """
    node = need_node("set_param")
    key = _parameter_key(param_name)
    if param_name.startswith("~") or \
            _on_server(lambda server: server.set(key, param_value)) is _unspecified:
        node.params.set(key, param_value)


def has_param(param_name: str) -> bool:
    """Whether get_param would find the parameter."""
    try:
        get_param(param_name)
    except KeyError:
        return False
    return True


def delete_param(param_name: str) -> None:
    """Deletes it (and what is below it) wherever it is; KeyError when it is nowhere."""
    from launcher.bus.graph_parameters import Missing

    node = need_node("delete_param")
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
        node.params.drop(found)
    elif not deleted:
        raise KeyError(param_name)


def get_param_names() -> list[str]:
    """Every parameter name the node can read: its own and the server's."""
    node = need_node("get_param_names")
    found_names = {k if k.startswith("/") else f"{state.name}/{k}" for k in node.parameters}
    found = _on_server(lambda server: server.names())
    return sorted(found_names | set(found if found is not _unspecified else ()))


def search_param(param_name: str) -> str | None:
    """The resolved name of a parameter that is set, or None."""
    key = _parameter_key(param_name)
    return key if has_param(param_name) else None


def wait_for_message(topic: str, topic_type: Any, timeout: float | None = None) -> Any:
    """The next message on `topic`: ROSException after `timeout` seconds,
    ROSInterruptException at shutdown.
    """
    need_node("wait_for_message")
    first = FirstMessage()
    subscriber = Subscriber(topic, topic_type, first)
    try:
        end = None if timeout is None else _time.monotonic() + timeout
        while not first.wait(0.1):
            if state.shutdown.is_set():
                raise ROSInterruptException("rospy shutdown")
            if end is not None and _time.monotonic() >= end:
                raise ROSException(f"timeout exceeded while waiting for message on topic "
                                   f"{subscriber.name}")
        return first.message
    finally:
        subscriber.unregister()


def get_published_topics(namespace: str = "/") -> list[list[str]]:
    """[[topic, type], …] of the graph's published topics under `namespace`."""
    from launcher.bus import graph, keys

    node = need_node("get_published_topics")
    found: dict[str, str] = {}
    for entity in graph.entities(node.graph_session(), 0.5):
        if entity.kind == keys.PUBLISHER and entity.topic.startswith(namespace):
            package, _, short = entity.type_name.split("/")
            found[entity.topic] = f"{package}/{short}"
    return [[name, kind] for name, kind in sorted(found.items())]
