"""`tf2_echo SOURCE TARGET [RATE]`: where TARGET is in SOURCE, printed as tf2_echo prints it,
RATE times a second (1); while the transform cannot be looked up, why not, once a second."""

from __future__ import annotations

import math
import sys
from typing import Any

from launcher.bus.node import Node
from launcher.bus.tf_tree import BufferCore, TransformException
from launcher.errors import UsageError, reported
from launcher.nodes.tf_feed import feed

USAGE = "usage: tf2_echo source_frame target_frame [echo_rate]"


def _rpy(q: tuple[float, ...]) -> tuple[float, float, float]:
    x, y, z, w = q
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return roll, pitch, yaw


def describe(pose: Any, stamp: int) -> str:
    (tx, ty, tz), q = pose
    x, y, z, w = q
    rpy = _rpy(q)
    matrix = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), tx],
              [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), ty],
              [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), tz],
              [0.0, 0.0, 0.0, 1.0]]
    lines = [f"At time {stamp // 1_000_000_000}.{stamp % 1_000_000_000:09d}",
             f"- Translation: [{tx:.3f}, {ty:.3f}, {tz:.3f}]",
             f"- Rotation: in Quaternion (xyzw) [{x:.3f}, {y:.3f}, {z:.3f}, {w:.3f}]",
             f"- Rotation: in RPY (radian) [{rpy[0]:.3f}, {rpy[1]:.3f}, {rpy[2]:.3f}]",
             f"- Rotation: in RPY (degree) [{math.degrees(rpy[0]):.3f}, "
             f"{math.degrees(rpy[1]):.3f}, {math.degrees(rpy[2]):.3f}]",
             "- Matrix:"]
    lines += ["  " + " ".join(f"{v:6.3f}" for v in row) for row in matrix]
    return "\n".join(lines)


def run(argv: list[str]) -> int:
    node = Node("tf2_echo", argv=argv)
    try:
        words = list(node.args)
        if len(words) not in (2, 3):
            raise UsageError(f"expected a source frame, a target frame and maybe a rate, got "
                             f"{len(words)} arguments\n{USAGE}")
        source, target = words[0], words[1]
        try:
            rate = float(words[2]) if len(words) == 3 else 1.0
        except ValueError:
            raise UsageError(f"the echo rate '{words[2]}' is not a number\n{USAGE}") from None
        if not rate > 0:
            raise UsageError(f"the echo rate must be above 0, got {words[2]}\n{USAGE}")
        tree = BufferCore()

        feed(node, tree, "tf2_echo")
        logger = node.get_logger()
        while not node.interrupted:
            node.spin(1.0 / rate)
            if node.interrupted:
                break
            try:
                pose, stamp = tree.lookup(source, target, 0)
            except TransformException as exc:
                logger.info(f"Waiting for transform {source} ->  {target}: {exc}")
                continue
            print(describe(pose, stamp), flush=True)
        return 0
    finally:
        node.destroy_node()


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "tf2_echo")


if __name__ == "__main__":
    sys.exit(main())
