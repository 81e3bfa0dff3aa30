"""sensor_msgs_py: ROS 2's helpers for sensor messages (point_cloud2)."""
