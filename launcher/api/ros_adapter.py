"""launch_ros.ros_adapters: the launch's own ROS node (`get_ros_node(context)`), for actions
and handlers of the user's that call services or read topics. It is made on first use, joins
the launch's graph with the environment the launch gives its nodes, spins in a thread of its
own, and is shut down with the launch."""

from __future__ import annotations

import os
import threading
from typing import Any

_LOCAL = "ros_adapter"


class ROSAdapter:
    """An rclpy context, a node and an executor spinning in a thread."""

    def __init__(self, *, argv: list[str] | None = None, autostart: bool = True) -> None:
        self.__argv = list(argv or [])
        self.__context: Any = None
        self.__node: Any = None
        self.__executor: Any = None
        self.__thread: threading.Thread | None = None
        if autostart:
            self.setup()

    def setup(self) -> None:
        import rclpy
        from rclpy.executors import SingleThreadedExecutor

        self.__context = rclpy.Context()
        rclpy.init(args=self.__argv, context=self.__context)
        self.__node = rclpy.create_node(f"launch_ros_{os.getpid()}", context=self.__context)
        self.__executor = SingleThreadedExecutor(context=self.__context)
        self.__executor.add_node(self.__node)
        self.__thread = threading.Thread(target=self._spin, daemon=True, name="launch_ros")
        self.__thread.start()

    def _spin(self) -> None:
        import contextlib

        with contextlib.suppress(Exception):  # (its end is the context's shutdown)
            while self.__context.ok():
                self.__executor.spin_once(timeout_sec=0.1)

    def shutdown(self) -> None:
        if self.__context is None:
            return
        self.__context.try_shutdown()
        if self.__thread is not None:
            self.__thread.join(timeout=5)
        self.__node.destroy_node()

    @property
    def ros_context(self) -> Any:
        return self.__context

    @property
    def ros_node(self) -> Any:
        return self.__node

    @property
    def ros_executor(self) -> Any:
        return self.__executor


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
