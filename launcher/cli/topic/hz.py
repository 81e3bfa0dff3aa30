"""`launcher topic hz`: the rate of one or more topics, printed every second."""

from __future__ import annotations

import argparse
import time
from collections import deque
from itertools import pairwise

from launcher.bus.session import open_session
from launcher.cli import completion, positive_count
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.topic.lookup import topic_name, type_of


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="+", metavar="topic", help="the topics").completer = \
        completion.topics  # type: ignore[attr-defined]
    parser.add_argument("-w", "--window", type=positive_count, default=10000, metavar="N",
                        help="how many of the latest messages the rate is taken over (messages, "
                             "as ROS 2 counts it; default 10000)")
    parser.add_argument("--wall-time", action="store_true",
                        help="accepted: the rate is always taken on the wall clock")
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    """As `ros2 topic hz`: every second, each topic's rate over its last `--window` messages,
    with the shortest and longest gap and their spread."""
    from launcher.bus.node import Node

    session = open_session("client")
    node = Node("_launcher_topic_hz", argv=[], parameter_services=False, session=session,
                space=space_of(args))
    topics = [topic_name(t) for t in args.topics]
    stamps: dict[str, deque[float]] = {t: deque(maxlen=args.window + 1) for t in topics}
    for topic in topics:
        node.create_subscription(type_of(session, topic, None, space_of(args)), topic,
                                 lambda _m, kept=stamps[topic]: kept.append(time.monotonic()),
                                 raw=True)
    printed = dict.fromkeys(topics, 0.0)
    while not node.interrupted:
        node.spin(1.0)
        for topic in topics:
            kept = stamps[topic]
            if len(topics) > 1:
                print(f"{topic}:")
            if len(kept) < 2 or kept[-1] == printed[topic]:
                print("no new messages", flush=True)
                continue
            printed[topic] = kept[-1]
            print(rate_lines(list(kept)), flush=True)
    node.destroy_node()
    return 0


def rate_lines(stamps: list[float]) -> str:
    """`ros2 topic hz`'s two lines for the arrival times `stamps` (seconds)."""
    gaps = [b - a for a, b in pairwise(stamps)]
    mean = sum(gaps) / len(gaps)
    spread = (sum((g - mean) ** 2 for g in gaps) / len(gaps)) ** 0.5
    rate = 1.0 / mean if mean > 0 else 0.0
    return (f"average rate: {rate:.3f}\n\tmin: {min(gaps):.3f}s max: {max(gaps):.3f}s "
            f"std dev: {spread:.5f}s window: {len(stamps)}")
