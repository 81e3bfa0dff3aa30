"""launch_testing_ros.pytest: launch_testing's pytest items, run by launch_testing_ros's
runner."""
