"""mujoco_ros2_control in launcher's sim: its hardware interface over an MJCF's own actuators
(system.py, with actuators.py and transmissions.py), the services of its
`mujoco_ros2_control_node` (services.py) and its ROS plugins (ros_plugins.py). The world plugin
that puts them together with controller_manager is launcher/sim/plugins/mujoco_ros2_control.py;
the `ros2_control_node` that starts it is launcher/nodes/mujoco_ros2_control_node.py."""
