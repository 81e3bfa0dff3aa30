"""`static_transform_publisher`: one static transform on `/tf_static`, latched, as tf2_ros's.

New-style arguments (`--x 1 --yaw 0.5 --frame-id map --child-frame-id odom`, any left out
are zero) and the old positional ones (`x y z yaw pitch roll frame child` or
`x y z qx qy qz qw frame child`, with ROS 2's deprecation warning). Bad arguments print
ROS 2's usage and exit 1.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from typing import Any

from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
from launcher.errors import UsageError
from launcher.nodes import running

USAGE = ("usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] "
         "[--qz QZ] [--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID "
         "--child-frame-id CHILD_FRAME_ID")
NUMBERS = ("x", "y", "z", "qx", "qy", "qz", "qw", "roll", "pitch", "yaw")


def parse(words: list[str]) -> tuple[tuple[float, ...], tuple[float, ...], str, str, bool]:
    """(translation, quaternion xyzw, frame, child, old style) from the arguments."""
    if words and not words[0].startswith("--"):
        return _old_style(words)
    parser = argparse.ArgumentParser(prog="static_transform_publisher", add_help=False)
    for name in NUMBERS:
        parser.add_argument(f"--{name}", type=float, default=None)
    parser.add_argument("--frame-id", required=True)
    parser.add_argument("--child-frame-id", required=True)
    try:
        args, extra = parser.parse_known_args(words)
    except SystemExit:
        raise UsageError(f"cannot read the arguments {' '.join(words) or '(none)'}\n{USAGE}") \
            from None
    if extra:
        raise UsageError(f"unknown arguments {' '.join(extra)}\n{USAGE}")
    quaternion = (args.qx, args.qy, args.qz, args.qw)
    angles = (args.roll, args.pitch, args.yaw)
    if any(v is not None for v in quaternion) and any(v is not None for v in angles):
        raise UsageError(f"give a rotation as a quaternion or as roll, pitch and yaw, not "
                         f"both\n{USAGE}")
    if any(v is not None for v in quaternion):
        rotation = tuple(v or 0.0 for v in quaternion[:3]) + \
            (1.0 if args.qw is None else args.qw,)
    else:
        rotation = _from_rpy(*(v or 0.0 for v in angles))
    return ((args.x or 0.0, args.y or 0.0, args.z or 0.0), _normal(rotation), args.frame_id,
            args.child_frame_id, False)


def _old_style(words: list[str]) -> tuple[tuple[float, ...], tuple[float, ...], str, str, bool]:
    if len(words) not in (8, 9):
        raise UsageError(f"expected 8 or 9 positional arguments (x y z yaw pitch roll frame "
                         f"child, or x y z qx qy qz qw frame child), got {len(words)}\n{USAGE}")
    count = len(words) - 2
    try:
        values = [float(w) for w in words[:count]]
    except ValueError as exc:
        raise UsageError(f"{exc}: the first {count} arguments are numbers\n{USAGE}") from None
    if count == 6:
        yaw, pitch, roll = values[3:6]
        rotation = _from_rpy(roll, pitch, yaw)
    else:
        rotation = tuple(values[3:7])
    return tuple(values[:3]), _normal(rotation), words[count], words[count + 1], True


def _from_rpy(roll: float, pitch: float, yaw: float) -> tuple[float, ...]:
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def _normal(q: tuple[float, ...]) -> tuple[float, ...]:
    norm = math.sqrt(sum(v * v for v in q))
    if not math.isfinite(norm) or norm < 1e-9:
        raise UsageError(f"the rotation {list(q)} is not a quaternion (its norm is {norm:g})"
                         f"\n{USAGE}")
    return tuple(v / norm for v in q)


def setup(node: Node) -> Any:
    translation, rotation, frame, child, old = parse(list(node.args))
    logger = node.get_logger()
    if old:
        logger.warning("Old-style arguments are deprecated; see --help for new-style arguments")
    if frame == child:
        raise UsageError(f"frame-id and child-frame-id are both '{frame}': a transform joins "
                         "two frames")
    stamp = node.get_clock().now()
    sec, nanosec = divmod(int(getattr(stamp, "nanoseconds", 0)), 1_000_000_000)
    message = node.message("tf2_msgs/msg/TFMessage", transforms=[node.message(
        "geometry_msgs/msg/TransformStamped",
        header=node.message("std_msgs/msg/Header", frame_id=frame, stamp=node.message(
            "builtin_interfaces/msg/Time", sec=sec, nanosec=nanosec)),
        child_frame_id=child, transform=node.message(
            "geometry_msgs/msg/Transform",
            translation=node.message("geometry_msgs/msg/Vector3", x=translation[0],
                                     y=translation[1], z=translation[2]),
            rotation=node.message("geometry_msgs/msg/Quaternion", x=rotation[0],
                                  y=rotation[1], z=rotation[2], w=rotation[3])))])
    publisher = node.create_publisher("tf2_msgs/msg/TFMessage", "/tf_static", LATCHED)
    publisher.publish(message)
    logger.info("Spinning until stopped - publishing transform\n"
                f"translation: ('{translation[0]:f}', '{translation[1]:f}', "
                f"'{translation[2]:f}')\n"
                f"rotation: ('{rotation[0]:f}', '{rotation[1]:f}', '{rotation[2]:f}', "
                f"'{rotation[3]:f}')\nfrom '{frame}' to '{child}'")
    return publisher


def main() -> int:
    if "-h" in sys.argv[1:] or "--help" in sys.argv[1:]:
        print(USAGE)
        return 0
    return running.run_node("static_transform_publisher", setup,
                            f"static_transform_publisher_{os.urandom(8).hex()}")


if __name__ == "__main__":
    sys.exit(main())
