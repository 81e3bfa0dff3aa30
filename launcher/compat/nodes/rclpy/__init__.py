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
import importlib
from typing import Any

from rclpy.context import Context  # noqa: F401 - rclpy.Context, as rclpy offers it
from rclpy.signals import (  # noqa: F401
    SignalHandlerOptions,
    install_signal_handlers,
    uninstall_signal_handlers,
    watch,
)
from rclpy.utilities import (  # noqa: F401
    get_default_context,
    get_rmw_implementation_identifier,
    ok,
    shutdown,
    try_shutdown,
)

__all__ = ["Context", "Future", "InitContextManager", "Parameter", "QoSProfile",
           "SignalHandlerOptions", "create_node", "get_default_context", "get_global_executor",
           "get_rmw_implementation_identifier", "init", "install_signal_handlers", "ok",
           "shutdown", "spin", "spin_once", "spin_until_future_complete", "try_shutdown",
           "uninstall_signal_handlers"]

_global_executor: Any = None
_ON_USE = {"Future": "rclpy.task", "Parameter": "rclpy.parameter", "QoSProfile": "rclpy.qos"}


class InitContextManager:
    """What `rclpy.init()` returns, having initialized the context: `with rclpy.init(): …`
    shuts down at the end."""

    def __init__(self, args: list[str] | None, context: Context | None, domain_id: int | None,
                 signal_handler_options: SignalHandlerOptions | None) -> None:
        self.context = get_default_context() if context is None else context
        if signal_handler_options is None:  # rclpy's: the default context handles signals
            signal_handler_options = SignalHandlerOptions.ALL \
                if self.context is get_default_context() else SignalHandlerOptions.NO
        self.installed_signal_handlers = signal_handler_options != SignalHandlerOptions.NO
        self.context.init(args, domain_id=domain_id)
        watch(self.context)
        install_signal_handlers(signal_handler_options)

    def __enter__(self) -> InitContextManager:
        return self

    def __exit__(self, *exc: Any) -> None:
        try_shutdown(context=self.context,
                     uninstall_handlers=self.installed_signal_handlers)


def init(*, args: list[str] | None = None, context: Context | None = None,
         domain_id: int | None = None,
         signal_handler_options: SignalHandlerOptions | None = None) -> InitContextManager:
    """Initialize the default (or the given) context with the command line `args`; SIGINT
    and SIGTERM handlers when it is the default context (or as `signal_handler_options`
    says)."""
    return InitContextManager(args, context, domain_id, signal_handler_options)


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
    from rclpy.custody import check_alive

    executor = executor or get_global_executor()
    check_alive(node)
    executor.add_node(node)
    return executor


def spin_once(node: Any, *, executor: Any = None, timeout_sec: float | None = None) -> None:
    """Run one ready callback of `node`, waiting up to `timeout_sec`."""
    from rclpy.custody import check_alive

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
    """`rclpy.Future`, `rclpy.QoSProfile`, … and `rclpy.executors`, `rclpy.qos`, … without
    importing them first."""
    if name in _ON_USE:
        return getattr(importlib.import_module(_ON_USE[name]), name)
    if name.startswith("_"):
        raise AttributeError(name)
    try:
        return importlib.import_module(f"rclpy.{name}")
    except ModuleNotFoundError:
        raise AttributeError(f"module 'rclpy' has no attribute '{name}'") from None
