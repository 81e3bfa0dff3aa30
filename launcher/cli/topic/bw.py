"""`launcher topic bw`: the bandwidth a topic uses, printed every second."""

from __future__ import annotations

import argparse
import time
from collections import deque

from launcher.bus.session import open_session
from launcher.cli import completion, positive_count
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.topic.lookup import topic_name, type_of


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="+", metavar="topic", help="the topics").completer = \
        completion.topics  # type: ignore[attr-defined]
    parser.add_argument("-w", "--window", type=positive_count, default=100, metavar="N",
                        help="how many of the latest messages it is taken over (default 100)")
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    """As `ros2 topic bw`: every second, bytes per second over the last `--window` messages,
    and the messages' sizes."""
    from launcher.bus.node import Node

    session = open_session("client")
    node = Node("_launcher_topic_bw", argv=[], parameter_services=False, session=session,
                space=space_of(args))
    topics = [topic_name(t) for t in args.topics]
    kept: dict[str, deque[tuple[float, int]]] = {t: deque(maxlen=args.window) for t in topics}
    for topic in topics:
        node.create_subscription(
            type_of(session, topic, None, space_of(args)), topic,
            lambda m, into=kept[topic]: into.append((time.monotonic(), len(m))), raw=True)
        print(f"Subscribed to [{topic}]", flush=True)
    while not node.interrupted:
        node.spin(1.0)
        for topic in topics:
            if len(topics) > 1:
                print(f"{topic}:")
            print(bandwidth_lines(list(kept[topic]), time.monotonic()), flush=True)
    node.destroy_node()
    return 0


def _size(count: float) -> str:
    for unit, scale in (("MB", 1e6), ("KB", 1e3)):
        if count >= scale:
            return f"{count / scale:.2f} {unit}"
    return f"{count:.0f} B"


def bandwidth_lines(samples: list[tuple[float, int]], now: float) -> str:
    """`ros2 topic bw`'s lines for (arrival time, size) samples."""
    if len(samples) < 2:
        return "no new messages" if not samples else "waiting for a second message"
    sizes = [size for _, size in samples]
    span = max(now - samples[0][0], 1e-9)
    return (f"{_size(sum(sizes) / span)}/s from {len(sizes)} messages\n"
            f"\tMessage size mean: {_size(sum(sizes) / len(sizes))} min: {_size(min(sizes))} "
            f"max: {_size(max(sizes))}")
