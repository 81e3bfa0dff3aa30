"""rclpy.impl: the pieces of rclpy's implementation package that node code imports."""
