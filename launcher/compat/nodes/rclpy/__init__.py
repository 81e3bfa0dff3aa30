"""rclpy for launcher's graph: the API of ROS 2's Python client library (Jazzy/Kilted) over
launcher's bus, for processes where no real rclpy is installed (see launcher/compat/finder.py).

    import rclpy
    from std_msgs.msg import String

    with rclpy.init():
        node = rclpy.create_node("talker")
        pub = node.create_publisher(String, "chatter", 10)
        ...
        rclpy.spin(node)

Actions (`rclpy.action`) and lifecycle nodes (`rclpy.lifecycle`) are modules of their own.
Not here (yet): waitables, type adaptation, content filters, QoS events (kept, never raised)
and the loaned-message API.
"""

from __future__ import annotations

import functools
import signal
import threading
from typing import Any

from rclpy.context import Context  # noqa: F401 - rclpy.Context, as rclpy offers it
from rclpy.utilities import get_default_context, ok, shutdown, try_shutdown  # noqa: F401

__all__ = ["Context", "create_node", "get_global_executor", "init", "ok", "shutdown", "spin",
           "spin_once", "spin_until_future_complete", "try_shutdown"]

_global_executor: Any = None


class SignalHandlerOptions:
    NO = 0
    SIGINT = 1
    SIGTERM = 2
    ALL = 3


class InitContextManager:
    """What `rclpy.init()` returns: `with rclpy.init(): …` shuts down at the end."""

    def __init__(self, context: Any) -> None:
        self.context = context

    def __enter__(self) -> InitContextManager:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.context.try_shutdown()


def init(*, args: list[str] | None = None, context: Any = None, domain_id: int | None = None,
         signal_handler_options: int | None = None) -> InitContextManager:
    """Initialize the default (or the given) context with the command line `args`."""
    context = context or get_default_context()
    context.init(args, domain_id=domain_id)
    options = SignalHandlerOptions.ALL if signal_handler_options is None else \
        signal_handler_options
    if options & SignalHandlerOptions.SIGTERM:
        _on_sigterm(context)
    return InitContextManager(context)


def _on_sigterm(context: Any) -> None:
    """SIGTERM ends spinning with ExternalShutdownException, as rclpy's handler does (a
    handler the program installed itself stays)."""
    if threading.current_thread() is not threading.main_thread():
        return
    if signal.getsignal(signal.SIGTERM) not in (signal.SIG_DFL, None):
        return

    def stop(number: int, frame: Any) -> None:
        from rclpy.executors import ExternalShutdownException

        context.interrupt()
        raise ExternalShutdownException()
    signal.signal(signal.SIGTERM, stop)


def get_global_executor() -> Any:
    """The executor spin() and spin_once() use when given none."""
    global _global_executor
    if _global_executor is None:
        from rclpy.executors import SingleThreadedExecutor

        _global_executor = SingleThreadedExecutor()
    return _global_executor


def create_node(node_name: str, **kwargs: Any) -> Any:
    """A Node (the Node constructor's keyword arguments)."""
    from rclpy.node import Node

    return Node(node_name, **kwargs)


def _executor_for(node: Any, executor: Any) -> Any:
    from rclpy.node import check_alive

    executor = executor or get_global_executor()
    check_alive(node)
    executor.add_node(node)
    return executor


def spin_once(node: Any, *, executor: Any = None, timeout_sec: float | None = None) -> None:
    """Run one ready callback of `node`, waiting up to `timeout_sec`."""
    from rclpy.node import check_alive

    executor = executor or get_global_executor()
    if type(executor).spin_once is _plain_spin_once():  # (not a subclass's own spin_once)
        check_alive(node)
        executor.spin_once_lent(node, timeout_sec)
        return
    executor = _executor_for(node, executor)
    try:
        executor.spin_once(timeout_sec=timeout_sec)
    finally:
        executor.remove_node(node)


@functools.cache
def _plain_spin_once() -> Any:
    from rclpy.executors import Executor

    return Executor.spin_once


def spin(node: Any, executor: Any = None) -> None:
    """Run `node`'s callbacks until the context shuts down."""
    executor = _executor_for(node, executor)
    try:
        while executor.context.ok():
            executor.spin_once()
    finally:
        executor.remove_node(node)


def spin_until_future_complete(node: Any, future: Any, executor: Any = None,
                               timeout_sec: float | None = None) -> None:
    """Run `node`'s callbacks until `future` is done or `timeout_sec`
    has passed.
    """
    executor = _executor_for(node, executor)
    try:
        executor.spin_until_future_complete(future, timeout_sec)
    finally:
        executor.remove_node(node)


def __getattr__(name: str) -> Any:
    """`rclpy.executors`, `rclpy.qos`, … without importing them first."""
    import importlib

    if name.startswith("_"):
        raise AttributeError(name)
    try:
        return importlib.import_module(f"rclpy.{name}")
    except ModuleNotFoundError:
        raise AttributeError(f"module 'rclpy' has no attribute '{name}'") from None
