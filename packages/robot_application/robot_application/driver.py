"""The driver, as the course's publisher.py: cmd_vel at 10 Hz out, the robot's x, y printed.

Parameters: `speed` (m/s, 0.5), `turn` (rad/s, 0.2), `print_rate` (Hz, 2). Topics are
relative, so in a namespace it drives that robot.
"""

from __future__ import annotations

import time

from launcher.bus.node import Node


def Driver() -> Node:  # noqa: N802  # the component's name, as a class would have it
    """The driver as a component (robot_application::Driver): the node, set up, not spun."""
    node = Node("driver")
    speed = float(node.declare_parameter("speed", 0.5).value)
    turn = float(node.declare_parameter("turn", 0.2).value)
    period = 1.0 / float(node.declare_parameter("print_rate", 2.0).value)
    last = [0.0]

    def on_odom(message) -> None:
        now = time.monotonic()
        if now - last[0] >= period:
            last[0] = now
            position = message.pose.pose.position
            print(f"X: {position.x:.3f}, Y: {position.y:.3f}", flush=True)

    node.create_subscription("nav_msgs/msg/Odometry", "odom", on_odom)
    publisher = node.create_publisher("geometry_msgs/msg/Twist", "cmd_vel")
    command = node.message("geometry_msgs/msg/Twist", linear={"x": speed}, angular={"z": turn})
    node.create_timer(0.1, lambda: publisher.publish(command), node.get_clock())  # sim time
    node.get_logger().info(f"driving at {speed} m/s, turning at {turn} rad/s")
    return node


def main() -> int:
    node = Driver()
    node.spin()
    node.destroy_node()
    return 0
