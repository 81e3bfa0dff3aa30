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

import struct
import sys
from typing import Any

import numpy as np

from launcher.bus.node import Node
from launcher.bus.qos import LATCHED, QoS
from launcher.errors import LaunchError
from launcher.nodes.kinematics import Tree

_HEAD = b"\x00\x01\x00\x00"
_STAMP = struct.Struct("<iI")
_SEVEN = struct.Struct("<7d")


def _string(text: str) -> bytes:
    data = text.encode() + b"\0"
    return struct.pack("<I", len(data)) + data


def pack_tf(sec: int, nanosec: int, parents: list[bytes], children: list[bytes],
            translations: np.ndarray, quats: np.ndarray) -> bytes:
    """tf2_msgs/msg/TFMessage as CDR; `parents`/`children` are `_string()`-encoded names.

    Packed directly: at 1 kHz with 20 joints this is the node's main cost, and building the
    message objects for a generic serializer costs several times more."""
    out = bytearray(_HEAD)
    out += struct.pack("<I", len(parents))
    stamp = _STAMP.pack(sec, nanosec)
    values = np.concatenate([translations, quats], axis=1).tolist()
    for parent, child, numbers in zip(parents, children, values, strict=True):
        out += b"\0" * (-(len(out) - 4) % 4)
        out += stamp
        out += parent
        out += b"\0" * (-(len(out) - 4) % 4)
        out += child
        out += b"\0" * (-(len(out) - 4) % 8)
        out += _SEVEN.pack(*numbers)
    return bytes(out)


class RobotStatePublisher:
    def __init__(self, node: Node) -> None:
        self.node = node
        self.log = node.get_logger()
        frequency = node.declare_parameter("publish_frequency", 20.0).value
        try:
            self.frequency = float(frequency)
        except (TypeError, ValueError):
            raise LaunchError(f"publish_frequency must be a number, got {frequency!r}") from None
        if not 0.0 <= self.frequency <= 1000.0:
            raise LaunchError(f"publish_frequency must be between 0 and 1000 Hz, got "
                              f"{self.frequency:g}")
        self.ignore_timestamp = bool(node.declare_parameter("ignore_timestamp", False).value)
        self.prefix = str(node.declare_parameter("frame_prefix", "").value or "")
        description = node.declare_parameter("robot_description", "").value
        if not node.has_parameter("robot_description") or not description:
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
        node.create_subscription("sensor_msgs/msg/JointState", "joint_states", self.on_joints,
                                 QoS(depth=10, reliable=False))
        node.add_on_set_parameters_callback(self.on_parameter)

    def _load(self, tree: Tree, description: str) -> None:
        self.tree = tree
        self._names = [_string(self.prefix + j.parent) for j in tree.moving]
        self._children = [_string(self.prefix + j.child) for j in tree.moving]
        self._mimics = [(i, tree.index[j.mimic[0]], j.mimic[1], j.mimic[2])
                        for i, j in enumerate(tree.moving)
                        if j.mimic and j.mimic[0] in tree.index]
        self._warned: set[str] = set()
        self._last_stamp: float | None = None
        self.description_pub.publish(self.node.message("std_msgs/msg/String", data=description))
        fixed = tree.fixed
        if fixed:
            xyz = np.array([j.xyz for j in fixed], dtype=float)
            quat = np.array([j.quat for j in fixed], dtype=float)
            sec, nanosec = divmod(self.node.get_clock().now().nanoseconds, 1_000_000_000)
            self.static_pub.publish_raw(pack_tf(
                sec, nanosec, [_string(self.prefix + j.parent) for j in fixed],
                [_string(self.prefix + j.child) for j in fixed], xyz, quat))
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
        self._load(tree, str(value))

    def on_joints(self, message: Any) -> None:
        names, positions = message.name, message.position
        if len(names) != len(positions):
            self.log.warning(f"dropping a joint_states message: {len(names)} names but "
                             f"{len(positions)} positions")
            return
        stamp = message.header.stamp.sec + message.header.stamp.nanosec * 1e-9
        if not self.ignore_timestamp:
            if self._last_stamp is not None and stamp < self._last_stamp:
                self._last_stamp = None  # time went backwards: a sim reset
            if self._last_stamp is not None and self.frequency > 0 and \
                    stamp - self._last_stamp < 1.0 / self.frequency - 1e-9:
                return
            self._last_stamp = stamp
        index = self.tree.index
        chosen: list[int] = []
        values: list[float] = []
        for name, value in zip(names, positions, strict=True):
            i = index.get(name)
            if i is None:
                if name not in self._warned:
                    self._warned.add(name)
                    self.log.warning(f"joint '{name}' in joint_states is not a moving joint of "
                                     f"robot '{self.tree.name}' (warned once)")
                continue
            chosen.append(i)
            values.append(value)
        for i, master, multiplier, offset in self._mimics:
            if master in chosen:
                chosen.append(i)
                values.append(values[chosen.index(master)] * multiplier + offset)
        if not chosen:
            return
        full = np.zeros(len(self.tree.moving))
        full[chosen] = values
        translation, quat = self.tree.transforms(full)
        self.tf_pub.publish_raw(pack_tf(
            message.header.stamp.sec, message.header.stamp.nanosec,
            [self._names[i] for i in chosen], [self._children[i] for i in chosen],
            translation[chosen], quat[chosen]))


def main() -> int:
    node = Node("robot_state_publisher")
    try:
        RobotStatePublisher(node)
        node.spin()
    except LaunchError as exc:
        print(f"[robot_state_publisher] error: {exc}", file=sys.stderr, flush=True)
        return 1
    finally:
        node.destroy_node()
    return 0


if __name__ == "__main__":
    sys.exit(main())
