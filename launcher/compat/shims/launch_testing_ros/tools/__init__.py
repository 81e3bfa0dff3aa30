"""launch_testing_ros.tools: launch_testing's output filter, with an RMW's own lines."""

from launch_testing_ros.tools.output import basic_output_filter

__all__ = ["basic_output_filter"]
