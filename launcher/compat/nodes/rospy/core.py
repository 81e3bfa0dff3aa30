"""rospy.core: the node's state in this process, its shutdown, and logging (rospy's own
core module holds the same)."""

from __future__ import annotations

import sys
import threading
import time as _time
from collections.abc import Callable
from typing import Any

from rospy.exceptions import ROSInitException

DEBUG, INFO, WARN, ERROR, FATAL = 1, 2, 4, 8, 16
LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}


class State:
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


state = State()  # the one node of the process, and its shutdown


def need_node(what: str) -> Any:
    """The node, or rospy's ROSInitException naming `what` before init_node."""
    if state.node is None:
        raise ROSInitException(f"{what}: the node is not initialized. Have you called "
                               "init_node()?")
    return state.node


def get_node_uri() -> str:
    """The node's XML-RPC URI: empty, as launcher's graph has no XML-RPC."""
    return ""


def resolve_name(name: str, caller_id: str | None = None) -> str:
    """A name resolved as the node resolves it (namespace, `~`, remaps)."""
    node = need_node("resolve_name")
    return node.resolve(name)


def is_shutdown() -> bool:
    """Whether the node has been shut down (Ctrl-C, SIGTERM, signal_shutdown)."""
    return state.shutdown.is_set()


def core_is_shutdown() -> bool:
    """As is_shutdown."""
    return state.shutdown.is_set()


def on_shutdown(hook: Callable[..., Any]) -> None:
    """Call `hook` (with no argument, or with the reason) when the node shuts down."""
    state.hooks.append(hook)


def signal_shutdown(reason: str) -> None:
    """Shut the node down for `reason`: hooks run, sleeps and spins end."""
    shut_down(reason, destroy=True)


def shut_down(reason: str, destroy: bool) -> None:
    """In a signal handler the node is only told to stop; it is destroyed at exit (closing
    its session inside a handler could interrupt a put under way)."""
    with state.lock:
        if state.shutdown.is_set():
            return
        state.reason = reason
        state.shutdown.set()
    for hook in state.hooks:
        try:
            hook()
        except TypeError:
            hook(reason)
    node = state.node
    if node is not None:
        node.shutdown()
        if destroy:
            node.destroy_node()


# --- logging ----------------------------------------------------------------------------------
def _log(level: int, message: Any, *args: Any) -> None:
    if level < state.level:
        return
    text = str(message) % args if args else str(message)
    stream = sys.stderr if level >= WARN else sys.stdout
    print(f"[{LEVEL_NAMES[level]}] [{_time.time():.6f}]: {text}", file=stream, flush=True)


def logdebug(msg: Any, *args: Any, **kwargs: Any) -> None:
    """Log at DEBUG (printf-style `args` fill `msg`)."""
    _log(DEBUG, msg, *args)


def loginfo(msg: Any, *args: Any, **kwargs: Any) -> None:
    """Log at INFO on stdout."""
    _log(INFO, msg, *args)


def logwarn(msg: Any, *args: Any, **kwargs: Any) -> None:
    """Log at WARN on stderr."""
    _log(WARN, msg, *args)


def logerr(msg: Any, *args: Any, **kwargs: Any) -> None:
    """Log at ERROR on stderr."""
    _log(ERROR, msg, *args)


def logfatal(msg: Any, *args: Any, **kwargs: Any) -> None:
    """Log at FATAL on stderr."""
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
