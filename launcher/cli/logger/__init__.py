"""`launcher logger get|set NODE …`: a node's logger levels through its logger service
(`~/get_logger_levels`, `~/set_logger_levels`, which rclpy offers with
enable_logger_service=True)."""
