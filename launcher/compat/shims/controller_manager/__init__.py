"""controller_manager's Python side, over launcher's rclpy: its services called from a node
(controller_manager_services) and the checks ros2_control users' launch tests import
(test_utils). A real controller_manager that the user installed wins."""
