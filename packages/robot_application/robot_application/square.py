"""Drives a square from odometry and reports how far from the start it closes.

Parameters: `side` (m, 1.0), `speed` (m/s, 0.3), `turn` (rad/s, 0.6). Each side is driven
until odometry says it is done, then the robot turns until its heading has changed by 90°.
"""

from __future__ import annotations

import math

from launcher.bus.node import Node


def yaw_of(q) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def main() -> int:
    node = Node("square")
    side = float(node.declare_parameter("side", 1.0).value)
    speed = float(node.declare_parameter("speed", 0.3).value)
    turn = float(node.declare_parameter("turn", 0.6).value)
    state = {"pose": None}
    node.create_subscription("nav_msgs/msg/Odometry", "odom",
                             lambda m: state.__setitem__("pose", m.pose.pose))
    publisher = node.create_publisher("geometry_msgs/msg/Twist", "cmd_vel")

    def drive(v: float, w: float) -> None:
        publisher.publish(node.message("geometry_msgs/msg/Twist", linear={"x": v},
                                       angular={"z": w}))

    while state["pose"] is None and not node.interrupted:
        node.spin(0.1)
    start = state["pose"].position
    origin = (start.x, start.y)
    for leg in range(4):
        begin = state["pose"].position
        while math.hypot(state["pose"].position.x - begin.x,
                         state["pose"].position.y - begin.y) < side and not node.interrupted:
            drive(speed, 0.0)
            node.spin(0.05)
        heading = yaw_of(state["pose"].orientation)
        while abs(math.remainder(yaw_of(state["pose"].orientation) - heading, 2 * math.pi)) \
                < math.pi / 2 and not node.interrupted:
            drive(0.0, turn)
            node.spin(0.05)
        print(f"leg {leg + 1} done", flush=True)
    drive(0.0, 0.0)
    end = state["pose"].position
    print(f"closing error: {math.hypot(end.x - origin[0], end.y - origin[1]):.3f} m "
          f"after a {side:g} m square", flush=True)
    node.destroy_node()
    return 0
