"""rospy.core: the node's state in this process, its shutdown and hooks, logging, and what
rospy.core re-exports from rospy.names (as rospy's own core module does)."""

from __future__ import annotations

import os
import threading
from collections.abc import Callable
from typing import Any

from rospy.exceptions import ROSException, ROSInitException
from rospy.impl import log as _log
from rospy.impl.log import (  # noqa: F401
    DEBUG,
    ERROR,
    FATAL,
    INFO,
    LEVEL_NAMES,
    WARN,
    LoggingIdentical,
    LoggingOnce,
    LoggingThrottle,
)
from rospy.impl.validators import ParameterInvalid
from rospy.names import *  # noqa: F403 (rospy.core re-exports rospy.names)
from rospy.names import __all__ as _names
from rospy.names import valid_name_validator_resolved

MASTER_NAME = "master"  # the name ROS 1 reserves for its master
ROSRPC = "rosrpc://"


class State:
    def __init__(self) -> None:
        self.node: Any = None
        self.name = "/unnamed"
        self.shutdown = threading.Event()
        self.in_shutdown = False  # hooks are running; is_shutdown() is not yet true
        self.reason = ""
        # client hooks (no argument) run first, then pre-shutdown and shutdown hooks (reason)
        self.hooks: dict[str, list[Callable[..., Any]]] = {"client": [], "pre": [], "post": []}
        self.pending: list[Any] = []  # publishers/subscribers made before init_node
        self.lock = threading.RLock()
        self.spinner: threading.Thread | None = None
        self.graph: Any = None  # the graph's parameter server's client, once asked
        self.initialized = False
        self.uri: str | None = None


state = State()  # the one node of the process, and its shutdown


def need_node(what: str) -> Any:
    """The node, or rospy's ROSInitException naming `what` before init_node."""
    if state.node is None:
        raise ROSInitException(f"{what}: the node is not initialized. Have you called "
                               "init_node()?")
    return state.node


def is_initialized() -> bool:
    """Whether the node has been initialized (init_node has run)."""
    return state.initialized


def set_initialized(initialized: bool) -> None:
    """Mark the node as initialized (init_node does) or not."""
    state.initialized = initialized


def get_node_uri() -> str | None:
    """The node's URI as set_node_uri gave it (launcher's graph has no XML-RPC: None)."""
    return state.uri


def set_node_uri(uri: str) -> None:
    """Record the node's URI (it does not change how the node is reached)."""
    state.uri = uri


def get_ros_root(required: bool = False, env: Any = None) -> str | None:
    """ROS_ROOT from the environment; ROSException when `required` and it is not set."""
    ros_root = (os.environ if env is None else env).get("ROS_ROOT")
    if required and not ros_root:
        raise ROSException("ROS_ROOT is not set")
    return ros_root


def parse_rosrpc_uri(uri: str) -> tuple[str, int]:
    """(address, port) of a `rosrpc://host:port` URI; ParameterInvalid when it is not one."""
    if not uri.startswith(ROSRPC):
        raise ParameterInvalid(f"Invalid protocol for ROS service URL: {uri}")
    address = uri[len(ROSRPC):].partition("/")[0]
    try:
        host, port = address.split(":")
        return host, int(port)
    except ValueError:
        raise ParameterInvalid(f"ROS service URL is invalid: {uri}") from None


def deprecated(func: Callable[..., Any]) -> Callable[..., Any]:
    """Decorate `func` to warn with DeprecationWarning when it is called."""
    import functools

    @functools.wraps(func)
    def warned(*args: Any, **kwargs: Any) -> Any:
        import warnings

        warnings.warn(f"Call to deprecated function {func.__name__}.",
                      category=DeprecationWarning, stacklevel=2)
        return func(*args, **kwargs)
    return warned


def is_topic(param_name: str) -> Callable[[Any, str], str]:
    """A validator of topic names (resolved; not the global namespace)."""
    def validator(param_value: Any, caller_id: str) -> str:
        resolved = valid_name_validator_resolved(param_name, param_value, caller_id)
        if param_value == "/":
            raise ParameterInvalid(f"ERROR: parameter [{param_name}] cannot be the global "
                                   "namespace")
        return resolved
    return validator


def xmlrpcapi(uri: str | None, cache: bool = True) -> Any:
    """An XML-RPC proxy of `uri` (None when it is not a URI); ROS 1 nodes speak XML-RPC."""
    if uri is None:
        return None
    from urllib.parse import urlparse
    from xmlrpc.client import ServerProxy

    parsed = urlparse(uri)
    if not parsed.scheme or not parsed.netloc:
        return None
    if not cache:
        return ServerProxy(uri)
    with state.lock:
        return _proxies.setdefault(uri, ServerProxy(uri))


_proxies: dict[str, Any] = {}


def configure_logging(node_name: str, level: int = 20) -> None:
    """Log the Python logger `rospy` to a file in ROS's log folder (ROS_LOG_DIR, else
    ROS_HOME/log, else ~/.ros/log), named after the node or by `__log:=`."""
    import logging

    mappings = get_mappings()  # noqa: F405 (from rospy.names)
    if "__log" in mappings:
        filename = os.path.abspath(mappings["__log"])
    else:
        filename = node_name.replace("/", "_").lstrip("_") + ".log"
        if filename == ".log":
            raise ROSException(f"invalid configure_logging parameter: {node_name}")
        home = os.environ.get("ROS_HOME") or os.path.join(os.path.expanduser("~"), ".ros")
        filename = os.path.join(os.environ.get("ROS_LOG_DIR") or os.path.join(home, "log"),
                                filename)
    os.makedirs(os.path.dirname(filename), exist_ok=True)
    logger = logging.getLogger("rospy")
    logger.setLevel(level)
    handler = logging.FileHandler(filename)
    handler.setFormatter(logging.Formatter("[%(name)s][%(levelname)s] %(asctime)s: "
                                           "%(message)s"))
    logger.addHandler(handler)


def __getattr__(name: str) -> Any:
    """NullHandler is a logging.Handler: made when first asked for, as importing logging
    costs every node's start."""
    if name == "NullHandler":
        import logging

        class NullHandler(logging.Handler):
            """A handler that drops every record."""

            def emit(self, record: Any) -> None:
                pass

        NullHandler.__qualname__ = "NullHandler"
        globals()["NullHandler"] = NullHandler
        return NullHandler
    raise AttributeError(f"module 'rospy.core' has no attribute '{name}'")


# --- shutdown ---------------------------------------------------------------------------------
def is_shutdown() -> bool:
    """Whether the node has been shut down (Ctrl-C, SIGTERM, signal_shutdown)."""
    return state.shutdown.is_set()


def core_is_shutdown() -> bool:
    """As is_shutdown."""
    return state.shutdown.is_set()


def is_shutdown_requested() -> bool:
    """Whether shutdown has begun: true while the hooks run, before is_shutdown() is."""
    return state.in_shutdown


def _add_hook(h: Callable[..., Any], kind: str, with_reason: bool) -> None:
    if not callable(h):
        raise TypeError(f"shutdown hook [{h}] must be a function or callable object: "
                        f"{type(h)}")
    if state.shutdown.is_set():  # already down: called at once, as rospy does
        h("already shutdown") if with_reason else h()
        return
    with state.lock:
        state.hooks[kind].append(h)


def add_client_shutdown_hook(h: Callable[[], Any]) -> None:
    """Call `h()` first when the node shuts down (rospy.on_shutdown)."""
    _add_hook(h, "client", with_reason=False)


def add_preshutdown_hook(h: Callable[[str], Any]) -> None:
    """Call `h(reason)` when the node shuts down, before the shutdown hooks."""
    _add_hook(h, "pre", with_reason=True)


def add_shutdown_hook(h: Callable[[str], Any]) -> None:
    """Call `h(reason)` when the node has shut down."""
    _add_hook(h, "post", with_reason=True)


def signal_shutdown(reason: str) -> None:
    """Shut the node down for `reason`: hooks run, sleeps and spins end."""
    shut_down(reason, destroy=True)


def shut_down(reason: str, destroy: bool) -> None:
    """In a signal handler the node is only told to stop; it is destroyed at exit (closing
    its session inside a handler could interrupt a put under way)."""
    with state.lock:
        if state.shutdown.is_set() or state.in_shutdown:
            return
        state.in_shutdown, state.reason = True, reason
        hooks = {kind: list(found) for kind, found in state.hooks.items()}
        for found in state.hooks.values():
            found.clear()
    _run(hooks["client"], ())
    _run(hooks["pre"], (reason,))
    state.shutdown.set()
    _run(hooks["post"], (reason,))
    node = state.node
    if node is not None:
        node.shutdown()
        if destroy:
            node.destroy_node()


def _run(hooks: list[Callable[..., Any]], args: tuple) -> None:
    import traceback

    for hook in hooks:
        try:
            hook(*args)
        except Exception:  # a hook's error is reported; the others still run
            traceback.print_exc()


def register_signals() -> None:
    """Shut the node down on SIGINT and SIGTERM (then call the handlers that were there)."""
    import signal

    for number in (signal.SIGTERM, signal.SIGINT):
        previous = signal.getsignal(number)

        def handler(sig: int, frame: Any, previous: Any = previous) -> None:
            shut_down(f"signal-{sig}", destroy=False)
            if callable(previous) and previous is not signal.default_int_handler:
                previous(sig, frame)
        signal.signal(number, handler)


# --- logging ----------------------------------------------------------------------------------
logdebug, loginfo, logwarn, logerr, logfatal = (
    _log.plain(level) for level in (DEBUG, INFO, WARN, ERROR, FATAL))
logout = loginfo
logerror = logerr
logwarning = logwarn
logdebug_throttle, loginfo_throttle, logwarn_throttle, logerr_throttle, logfatal_throttle = (
    _log.throttled(level) for level in (DEBUG, INFO, WARN, ERROR, FATAL))
logdebug_throttle_identical, loginfo_throttle_identical, logwarn_throttle_identical, \
    logerr_throttle_identical, logfatal_throttle_identical = (
        _log.throttled_identical(level) for level in (DEBUG, INFO, WARN, ERROR, FATAL))
logdebug_once, loginfo_once, logwarn_once, logerr_once, logfatal_once = (
    _log.once(level) for level in (DEBUG, INFO, WARN, ERROR, FATAL))
rospydebug, rospyinfo, rospywarn, rospyerr = (
    _log.internal(method) for method in ("debug", "info", "warning", "error"))

_LOGGING = [f"log{level}{kind}" for level in ("debug", "info", "warn", "err", "fatal")
            for kind in ("", "_once", "_throttle", "_throttle_identical")]
__all__ = [*_names, *_LOGGING, "logout", "logerror", "MASTER_NAME", "ROSRPC",
           "LoggingIdentical", "LoggingOnce", "LoggingThrottle", "ParameterInvalid",
           "ROSException", "ROSInitException", "add_client_shutdown_hook",
           "add_preshutdown_hook", "add_shutdown_hook", "configure_logging", "deprecated",
           "get_node_uri", "get_ros_root", "is_initialized", "is_shutdown",
           "is_shutdown_requested", "is_topic", "parse_rosrpc_uri", "register_signals",
           "rospydebug", "rospyerr", "rospyinfo", "rospywarn", "set_initialized",
           "set_node_uri", "signal_shutdown", "xmlrpcapi"]
