"""`tf2_monitor [SOURCE TARGET]`: each frame's broadcast rate and delay (the time a transform
arrives after its stamp), printed every second as tf2_monitor prints them; with two frames,
the delay of the chain between them too."""

from __future__ import annotations

import sys
import time
from collections import defaultdict, deque
from typing import Any

from launcher.bus.node import Node
from launcher.bus.tf_tree import BufferCore, TransformException
from launcher.bus.wire import stamp_seconds
from launcher.errors import UsageError, reported
from launcher.nodes.tf_feed import feed

WINDOW = 200  # arrivals kept per frame


def run(argv: list[str]) -> int:
    node = Node("tf2_monitor", argv=argv)
    try:
        words = list(node.args)
        if len(words) not in (0, 2):
            raise UsageError("usage: tf2_monitor [source_frame target_frame]")
        arrivals: dict[str, deque[tuple[float, float]]] = defaultdict(
            lambda: deque(maxlen=WINDOW))
        tree = BufferCore()

        def arrived(t: Any, static: bool) -> None:
            stamp = stamp_seconds(t.header.stamp)
            arrivals[t.child_frame_id].append((time.monotonic(),
                                               0.0 if static else _seconds(node) - stamp))
        feed(node, tree, "tf2_monitor", arrived)
        print("Gathering data on all frames for 10 seconds...", flush=True) if not words \
            else print(f"Waiting for transform chain to become available between "
                       f"{words[0]} and {words[1]}", flush=True)
        while not node.interrupted:
            node.spin(1.0)
            if node.interrupted:
                break
            print(report(arrivals, words, tree), flush=True)
    finally:
        node.destroy_node()
    return 0


def _seconds(node: Node) -> float:
    """The node's time (sim time under use_sim_time), seconds."""
    now = node.get_clock().now()
    return now.nanoseconds / 1e9 if hasattr(now, "nanoseconds") else time.time()


def report(arrivals: dict[str, deque[tuple[float, float]]], words: list[str],
           tree: BufferCore) -> str:
    lines = ["", "", f"RESULTS: for {' to '.join(words) if words else 'all Frames'}"]
    if words:
        try:
            tree.lookup(words[0], words[1], 0)
            lines.append(f"Chain is: {words[0]} -> {words[1]}")
        except TransformException as exc:
            lines.append(f"Chain not found: {exc}")
    lines += ["", "Frames:"]
    for frame in sorted(arrivals):
        seen = list(arrivals[frame])
        delays = [d for _, d in seen]
        span = seen[-1][0] - seen[0][0]
        rate = (len(seen) - 1) / span if span > 0 else 0.0
        lines.append(f"Frame: {frame}, published by <no authority available>, Average "
                     f"Delay: {sum(delays) / len(delays):.6g}, Max Delay: "
                     f"{max(delays):.6g}, Rate: {rate:.1f} Hz")
    return "\n".join(lines)


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "tf2_monitor")


if __name__ == "__main__":
    sys.exit(main())
