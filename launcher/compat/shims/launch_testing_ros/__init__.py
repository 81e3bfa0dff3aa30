"""launch_testing_ros over launcher's rclpy: WaitForTopics, for a launch test's active tests
to wait for messages on topics, and tools.basic_output_filter. A real launch_testing_ros that
the user installed wins."""

from launch_testing_ros import tools
from launch_testing_ros.wait_for_topics import WaitForTopics

__all__ = ["WaitForTopics", "tools"]
