"""launch_testing_ros over launcher's rclpy: WaitForTopics, for a launch test's active tests
to wait for messages on topics, DataRepublisher and MessagePump, LaunchTestRunner, and
tools.basic_output_filter. A real launch_testing_ros that the user installed wins."""

from launch_testing_ros import tools
from launch_testing_ros.data_republisher import DataRepublisher
from launch_testing_ros.message_pump import MessagePump
from launch_testing_ros.test_runner import LaunchTestRunner
from launch_testing_ros.wait_for_topics import WaitForTopics

__all__ = ["DataRepublisher", "LaunchTestRunner", "MessagePump", "WaitForTopics", "tools"]
