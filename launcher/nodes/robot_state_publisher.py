"""robot_state_publisher: a URDF and joint states in, /tf and /tf_static out.

Parameters (ROS 2's): `robot_description` (required; the URDF), `publish_frequency` (20 Hz,
0–1000: the most /tf messages per second of joint_states time), `ignore_timestamp` (false:
true publishes for every joint_states message), `frame_prefix` (""). Publishes
`robot_description` (std_msgs/String, latched), `/tf_static` (fixed joints, latched: once and
whenever robot_description changes) and `/tf` (the moving joints named in each joint_states
message, mimic joints following their master, stamped with the message's header). Names,
namespace and remaps follow --ros-args. A joint_states message whose name and position
lengths differ is dropped with a warning; an unknown joint name is warned about once; time
going backwards (a sim reset) clears the rate limiter.
"""

from __future__ import annotations

import math
import sys
import threading
from collections.abc import Sequence
from types import SimpleNamespace
from typing import Any

from launcher.bus.declarations import Param
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED, QoS
from launcher.bus.wire import JointStateReader, TfLayout, pack_tf
from launcher.errors import LaunchError
from launcher.nodes import running
from launcher.nodes.kinematics import Tree
from launcher.sim.schedule import SLACK

# robot_state_publisher's parameters, ROS 2's names, types and ranges
PARAMETERS = (
    Param("robot_description", "string", "", "the URDF (or an SDF model) to publish"),
    Param("publish_frequency", "double", 20.0, "the most /tf messages a second, Hz",
          minimum=0.0, maximum=1000.0),
    Param("ignore_timestamp", "bool", False, "publish joint states whatever their stamps"),
    Param("frame_prefix", "string", "", "put before every frame's name"),
)


class RobotStatePublisher:
    def __init__(self, node: Node) -> None:
        self.node = node
        self.log = node.get_logger()
        params = node.params.declare(PARAMETERS)
        self.frequency = params["publish_frequency"]
        self.ignore_timestamp, self.prefix = params["ignore_timestamp"], params["frame_prefix"]
        description = params["robot_description"]
        if not description:
            raise LaunchError("parameter robot_description is missing or empty: give the URDF "
                              "(-p robot_description:=… or, in a launch file, "
                              "$(command 'xacro robot.xacro'))")
        self.tree = Tree.parse(str(description))
        self.description_pub = node.create_publisher("std_msgs/msg/String", "robot_description",
                                                     LATCHED)
        self.static_pub = node.create_publisher("tf2_msgs/msg/TFMessage", "/tf_static",
                                                LATCHED)
        self.tf_pub = node.create_publisher("tf2_msgs/msg/TFMessage", "/tf", QoS(depth=100))
        self._load(self.tree, str(description))
        self.reader = JointStateReader()
        # joint_states is handled on Zenoh's thread (at 1 kHz the hand-over to the executor
        # cost more than the work); a lock keeps it apart from parameter changes.
        self._lock = threading.Lock()
        self._bad_warned = False
        # joint_states is listened to only while /tf has a subscriber: with no one to tell,
        # the transforms are not worked out (and a lazy bridge, the sim behind it, rest too)
        self._joint_states: Any = None
        node.watch_subscribers(self.tf_pub, self._on_tf_subscribers)
        node.add_on_set_parameters_callback(self.on_parameter)

    def _on_tf_subscribers(self, matching: bool) -> None:
        if matching and self._joint_states is None:
            self._joint_states = self.node.create_subscription(
                "sensor_msgs/msg/JointState", "joint_states", self.on_payload,
                QoS(depth=10, reliable=False), raw=True, inline=True)
        elif not matching and self._joint_states is not None:
            self._joint_states.destroy()
            self._joint_states = None

    def _load(self, tree: Tree, description: str) -> None:
        self.tree = tree
        self._mimics = [(i, tree.index[j.mimic[0]], j.mimic[1], j.mimic[2])
                        for i, j in enumerate(tree.moving)
                        if j.mimic and j.mimic[0] in tree.index]
        self._plans: dict[tuple[str, ...], Any] = {}
        self._warned: set[str] = set()
        self._last_stamp: float | None = None
        # any object with the fields serialises: no message classes (rosbags') needed here
        self.description_pub.publish(SimpleNamespace(data=description))
        fixed = tree.fixed
        if fixed:
            xyz, quat = [j.xyz for j in fixed], [j.quat for j in fixed]
            sec, nanosec = divmod(self.node.get_clock().now().nanoseconds, 1_000_000_000)
            self.static_pub.publish_raw(pack_tf(
                sec, nanosec, [self.prefix + j.parent for j in fixed],
                [self.prefix + j.child for j in fixed], xyz, quat))
        self.log.info(f"robot '{tree.name}': {len(tree.moving)} moving joints, {len(fixed)} "
                      f"fixed, root '{tree.root}'")

    def on_parameter(self, name: str, value: Any) -> None:
        if name != "robot_description":
            return
        try:
            tree = Tree.parse(str(value))
        except LaunchError as exc:
            self.log.error(f"the new robot_description is not used: {exc}")
            return
        with self._lock:
            self._load(tree, str(value))

    def on_payload(self, payload: bytes) -> None:
        """One joint_states message (on Zenoh's thread). A malformed one is dropped with one
        warning for them all, never a traceback per message."""
        try:
            sec, nanosec, names, positions = self.reader.read(payload)
            with self._lock:
                self.on_joints(sec, nanosec, names, positions)
        except Exception as exc:  # noqa: BLE001 - whatever a message holds, keep running
            if not self._bad_warned:
                self._bad_warned = True
                self.log.warning(f"dropping joint_states messages that are not a valid "
                                 f"sensor_msgs/msg/JointState (the first: {exc or type(exc)}); "
                                 f"warned once")

    def on_joints(self, sec: int, nanosec: int, names: list[str],
                  positions: Sequence[float]) -> None:
        if len(names) != len(positions):
            raise ValueError(f"{len(names)} names but {len(positions)} positions")
        if not all(map(math.isfinite, positions)):
            raise ValueError("a position is not finite")
        stamp = sec + nanosec * 1e-9
        if not self.ignore_timestamp:
            if self._last_stamp is not None and stamp < self._last_stamp:
                self._last_stamp = None  # time went backwards: a sim reset
            if self._last_stamp is not None and self.frequency > 0 and \
                    stamp - self._last_stamp < 1.0 / self.frequency - SLACK:
                return
            self._last_stamp = stamp
        key = tuple(names)
        plan = self._plans.get(key)
        if plan is None:
            plan = self._plans[key] = self._plan(names)
        take, rows, mimics, layout = plan
        if layout is None:
            return
        values = [positions[i] for i in take]
        for master, multiplier, offset in mimics:
            values.append(values[master] * multiplier + offset)
        translation, quat = self.tree.transforms(values, rows)
        self.tf_pub.publish_raw(layout.pack(sec, nanosec, translation, quat))

    def _plan(self, names: list[str]) -> tuple[list[int], list[int] | None,
                                               list[tuple[int, float, float]], TfLayout | None]:
        """For one list of joint names: which positions to use, for which joints (None: all,
        in order), the mimic joints appended (the index of their master among the values,
        multiplier, offset), and the /tf layout. Unknown names are warned about once."""
        index = self.tree.index
        take, rows = [], []
        for position, name in enumerate(names):
            row = index.get(name)
            if row is None:
                if name not in self._warned:
                    self._warned.add(name)
                    self.log.warning(f"joint '{name}' in joint_states is not a moving joint of "
                                     f"robot '{self.tree.name}' (warned once)")
                continue
            take.append(position)
            rows.append(row)
        mimics = []
        for row, master, multiplier, offset in self._mimics:
            if master in rows and row not in rows:
                mimics.append((rows.index(master), multiplier, offset))
                rows.append(row)
        if not rows:
            return take, rows, mimics, None
        moving = self.tree.moving
        layout = TfLayout([self.prefix + moving[r].parent for r in rows],
                          [self.prefix + moving[r].child for r in rows])
        every = rows == list(range(len(moving)))  # every joint, in order: no gathering
        return take, None if every else rows, mimics, layout


component = running.component("robot_state_publisher", RobotStatePublisher)


def main() -> int:
    return running.run_node("robot_state_publisher", RobotStatePublisher)


if __name__ == "__main__":
    sys.exit(main())
