"""`joint_state_publisher` (and `joint_state_publisher_gui`): the robot's moving joints on
`joint_states`, as ROS 2's joint_state_publisher publishes them.

The URDF comes from the `robot_description` parameter, else the latched `robot_description`
topic (as in Humble and later). Each revolute, continuous and prismatic joint is published
at its zero (0, or the middle of its limits when 0 is outside them; `zeros` sets one), a
mimic joint at its master's value × multiplier + offset (`use_mimic_tags`); joint states on
the topics of `source_list` override positions (and velocities, efforts); `rate` Hz (10).
The GUI's sliders need a desktop: joint_state_publisher_gui publishes the same and says, once,
how to move a joint instead (a JointState on one of its source_list topics, or
`launcher param set` of `zeros.<joint>`)."""

from __future__ import annotations

import sys
import threading
import xml.etree.ElementTree as ET
from typing import Any

from launcher.bus.declarations import Param
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED, QoS
from launcher.nodes import running
from launcher.nodes.kinematics import MOVING, Tree

# joint_state_publisher's parameters (`zeros.<joint>` too: a joint's starting position)
PARAMETERS = (
    Param("robot_description", "string", "", "the URDF (else the robot_description topic's)"),
    Param("rate", "double", 10.0, "joint_states messages a second, Hz", minimum=1e-3),
    Param("use_mimic_tags", "bool", True, "a mimic joint follows its master"),
    Param("source_list", "string_array", [], "JointState topics whose positions win"),
)


class JointStatePublisher:
    def __init__(self, node: Node, gui: bool = False) -> None:
        self.node, self.gui = node, gui
        self.log = node.get_logger()
        parameters = node.params.declare(PARAMETERS)
        self.rate, self.use_mimic = parameters["rate"], parameters["use_mimic_tags"]
        self.defaults = {k[len("zeros."):]: float(v) for k, v in node.parameters.items()
                         if k.startswith("zeros.")}
        self.lock = threading.Lock()
        self.positions: dict[str, float] = {}
        self.velocities: dict[str, float] = {}
        self.efforts: dict[str, float] = {}
        self.joints: list[str] = []
        self.mimics: dict[str, tuple[str, float, float]] = {}
        self.publisher = node.create_publisher("sensor_msgs/msg/JointState", "joint_states",
                                               QoS(depth=10))
        for topic in parameters["source_list"]:
            node.create_subscription("sensor_msgs/msg/JointState", topic, self.on_source)
        description = parameters["robot_description"]
        if description:
            self.load(str(description))
        else:
            self.log.info("Waiting for robot_description to be published on the "
                          "robot_description topic...")
            node.create_subscription("std_msgs/msg/String", "robot_description",
                                     lambda m: self.load(m.data), LATCHED)
        node.create_timer(1.0 / self.rate, self.publish)

    def load(self, text: str) -> None:
        tree = Tree.parse(text)
        limits = _limits(text)
        with self.lock:
            self.joints = [j.name for j in tree.joints if j.kind in MOVING]
            self.mimics = {j.name: j.mimic for j in tree.joints
                           if j.kind in MOVING and j.mimic and self.use_mimic}
            for name in self.joints:
                low, high = limits.get(name, (0.0, 0.0))
                zero = 0.0 if low <= 0.0 <= high or low == high else (low + high) / 2
                self.positions.setdefault(name, self.defaults.get(name, zero))
        if self.gui:
            self.log.info(
                "joint_state_publisher_gui: no desktop here for its sliders; it publishes the "
                "joints' zeros. Move a joint by publishing a sensor_msgs/msg/JointState on a "
                "topic of its source_list parameter, or with `launcher param set "
                f"{self.node.fully_qualified_name} zeros.<joint> <value>` before it starts")

    def on_source(self, message: Any) -> None:
        with self.lock:
            for i, name in enumerate(message.name):
                if name not in self.positions or name in self.mimics:
                    continue
                if i < len(message.position):
                    self.positions[name] = float(message.position[i])
                if i < len(message.velocity):
                    self.velocities[name] = float(message.velocity[i])
                if i < len(message.effort):
                    self.efforts[name] = float(message.effort[i])

    def publish(self) -> None:
        with self.lock:
            if not self.joints:
                return
            names = list(self.joints)
            positions = []
            for name in names:
                mimic = self.mimics.get(name)
                if mimic is not None and mimic[0] in self.positions:
                    master, multiplier, offset = mimic
                    positions.append(self.positions[master] * multiplier + offset)
                else:
                    positions.append(self.positions[name])
            velocities = [self.velocities.get(n, 0.0) for n in names] if self.velocities \
                else []
            efforts = [self.efforts.get(n, 0.0) for n in names] if self.efforts else []
        node = self.node
        now = node.get_clock().now()
        sec, nanosec = divmod(int(getattr(now, "nanoseconds", 0)), 1_000_000_000)
        self.publisher.publish(node.message(
            "sensor_msgs/msg/JointState",
            header=node.message("std_msgs/msg/Header", stamp=node.message(
                "builtin_interfaces/msg/Time", sec=sec, nanosec=nanosec)),
            name=names, position=positions, velocity=velocities, effort=efforts))


def _limits(text: str) -> dict[str, tuple[float, float]]:
    found = {}
    for joint in ET.fromstring(text).iter("joint"):
        limit = joint.find("limit")
        if limit is not None and joint.get("type") != "continuous":
            try:
                found[joint.get("name", "")] = (float(limit.get("lower", "0")),
                                                float(limit.get("upper", "0")))
            except ValueError:
                continue
    return found


def main() -> int:
    return running.run_node("joint_state_publisher", JointStatePublisher)


def gui_main() -> int:
    return running.run_node("joint_state_publisher_gui",
                            lambda node: JointStatePublisher(node, gui=True))


if __name__ == "__main__":
    sys.exit(main())
