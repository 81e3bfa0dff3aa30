"""rclpy.experimental.events_executor: rclpy's event-driven executor. launcher's executors
are driven by their nodes' bus events already, so it is the single-threaded one."""

from __future__ import annotations

from rclpy.executors import SingleThreadedExecutor


class EventsExecutor(SingleThreadedExecutor):
    """Runs callbacks in the thread that spins, as their events come."""
