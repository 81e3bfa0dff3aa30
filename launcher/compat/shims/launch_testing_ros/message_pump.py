"""launch_testing_ros.MessagePump: spins a node in a thread so that tests need not."""

from __future__ import annotations

import threading
from typing import Any


class MessagePump:
    """`start()` spins `node` (on an executor of `context`) until `stop()`."""

    def __init__(self, node: Any, context: Any = None) -> None:
        self._node, self._context = node, context
        self._running = True
        self._thread = threading.Thread(target=self._spin, name="msg_pump_thread")

    def start(self) -> None:
        self._thread.start()

    def stop(self) -> None:
        """Stop spinning (an Exception when the thread has not ended within 5 s)."""
        self._running = False
        self._thread.join(timeout=5.0)
        if self._thread.is_alive():
            raise Exception("Timed out waiting for message pump to stop")

    def _spin(self) -> None:
        from rclpy.executors import SingleThreadedExecutor

        executor = SingleThreadedExecutor(context=self._context)
        executor.add_node(self._node)
        while self._running:
            executor.spin_once(timeout_sec=1.0)


__all__ = ["MessagePump"]
