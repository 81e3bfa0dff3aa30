"""rclpy.impl.logging_severity.LoggingSeverity (the same as rclpy.logging's)."""

from rclpy.logging import LoggingSeverity

__all__ = ["LoggingSeverity"]
