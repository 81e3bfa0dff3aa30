"""launch_ros.ros_adapters: the launch's own ROS node (`get_ros_node(context)`), for actions
and handlers of the user's that call services or read topics. It is made on first use, joins
the launch's graph with the environment the launch gives its nodes, spins in a thread of its
own, and is shut down with the launch."""

from __future__ import annotations

import os
import threading
from operator import attrgetter
from typing import Any

_LOCAL = "ros_adapter"


class ROSAdapter:
    """An rclpy context, a node and an executor spinning in a thread."""

    def __init__(self, *, argv: list[str] | None = None, autostart: bool = True) -> None:
        self._argv = list(argv or [])
        self._context: Any = None
        self._node: Any = None
        self._executor: Any = None
        self._thread: threading.Thread | None = None
        if autostart:
            self.setup()

    def setup(self) -> None:
        import rclpy
        from rclpy.executors import SingleThreadedExecutor

        self._context = rclpy.Context()
        rclpy.init(args=self._argv, context=self._context)
        self._node = rclpy.create_node(f"launch_ros_{os.getpid()}", context=self._context)
        self._executor = SingleThreadedExecutor(context=self._context)
        self._executor.add_node(self._node)
        self._thread = threading.Thread(target=self._spin, daemon=True, name="launch_ros")
        self._thread.start()

    def _spin(self) -> None:
        import contextlib

        with contextlib.suppress(Exception):  # (its end is the context's shutdown)
            while self._context.ok():
                self._executor.spin_once(timeout_sec=0.1)

    def shutdown(self) -> None:
        if self._context is None:
            return
        self._context.try_shutdown()
        if self._thread is not None:
            self._thread.join(timeout=5)
        self._node.destroy_node()

    ros_context = property(attrgetter("_context"))
    ros_node = property(attrgetter("_node"))
    ros_executor = property(attrgetter("_executor"))


def get_ros_adapter(context: Any) -> ROSAdapter:
    """The launch's adapter: made on first use (on the launch's graph), shut down with the
    launch."""
    adapter = context.locals.get(_LOCAL) if hasattr(context.locals, "get") else None
    if adapter is None:
        from launcher.description.actions.event_handlers import OnShutdown

        previous = {k: os.environ.get(k) for k in context.environment}
        os.environ.update(context.environment)  # (the graph's router and domain)
        try:
            adapter = ROSAdapter()
        finally:
            for key, value in previous.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value
        context.extend_globals({_LOCAL: adapter})
        context.register_event_handler(OnShutdown(
            on_shutdown=lambda _event, _context: adapter.shutdown()))
    return adapter


def get_ros_node(context: Any) -> Any:
    return get_ros_adapter(context).ros_node
