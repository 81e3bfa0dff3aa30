"""`rosnode list | info | ping | kill`, as ROS 1's rosnode prints them. A node answers a
ping through its liveliness on the graph (there is no XML-RPC server to ask); `kill` asks
each node, on a key of launcher's own beside the graph, to shut down, and it ends as on
Ctrl-C (rospy's is_shutdown, rclpy's shutdown, the launch's supervision)."""
