"""`ros2_control_node`: controller_manager outside the sim, for testing controllers without
physics. The hardware is the `<ros2_control>` blocks of the robot description (the node's
`robot_description` parameter, else the latched `/robot_description` topic), every one run as
mock_components/GenericSystem (a block naming the sim's GazeboSimSystem is mocked too, with
a note). The manager updates at its `update_rate` on the wall clock."""

from __future__ import annotations

import sys
import time

from launcher.bus import ros_args
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
from launcher.control.description import parse
from launcher.control.hardware import make
from launcher.control.manager import ControllerManager
from launcher.control.manager_services import ManagerServices
from launcher.errors import LaunchError, reported

DESCRIPTION_WAIT = 30.0  # s to wait for /robot_description


def _description(node: Node) -> str:
    text = node.parameters.get("robot_description")
    if text:
        return str(text)
    got: list[str] = []
    node.create_subscription("std_msgs/msg/String", "/robot_description",
                             lambda m: got.append(m.data), LATCHED)
    node.get_logger().info("Waiting for data on 'robot_description' topic to finish "
                           "initialization")
    deadline = time.monotonic() + DESCRIPTION_WAIT
    while not got and time.monotonic() < deadline:
        node.spin_once(0.1)
    if not got:
        raise LaunchError(f"ros2_control_node: no robot description: give the "
                          f"'robot_description' parameter or publish /robot_description "
                          f"(waited {DESCRIPTION_WAIT:g} s)")
    node.get_logger().info("Received robot description from topic.")
    return got[0]


def run(argv: list[str]) -> int:
    node = Node("controller_manager", argv=argv)
    try:
        blocks = parse(_description(node), "robot_description")
        for block in blocks:
            if block.is_sim:
                node.get_logger().info(f"hardware '{block.name}' ({block.plugin}) runs as "
                                       f"mock_components/GenericSystem outside the sim")
        files = [s for kind, s in ros_args.parse(argv).parameter_sources if kind == "file"]
        manager = ControllerManager(node, [make(b) for b in blocks], files)
        ManagerServices(manager)
        period = 1.0 / manager.update_rate
        start = time.monotonic()
        node.create_timer(period, lambda: manager.update(time.monotonic() - start))
        node.spin()
        manager.shutdown()
        return 0
    finally:
        node.destroy_node()


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "ros2_control_node")




if __name__ == "__main__":
    sys.exit(main())
