"""`launcher topic delay`: how old a topic's messages are when they arrive (now -
header.stamp), printed every second."""

from __future__ import annotations

import argparse
from collections import deque
from typing import Any

from launcher.bus.qos import PROFILES
from launcher.bus.session import open_session
from launcher.bus.wire import stamp_seconds
from launcher.cli import completion, positive_count
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.topic.lookup import topic_name, type_of
from launcher.errors import UsageError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic (with a header)").completer = completion.topics  # type: ignore[attr-defined]
    parser.add_argument("-w", "--window", type=positive_count, default=10000, metavar="N",
                        help="how many of the latest messages it is taken over (default 10000)")
    parser.add_argument("--use-sim-time", action="store_true",
                        help="now is the simulation's time (/clock), for stamps in sim time")
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    """As `ros2 topic delay`: every second, how old messages are on arrival (their
    header.stamp against now), over the last `--window` messages."""
    from launcher.bus.node import Node
    from launcher.bus.types import registry

    session = open_session("client")
    argv = ["--ros-args", "-p", "use_sim_time:=true"] if args.use_sim_time else []
    node = Node("_launcher_topic_delay", argv=argv, parameter_services=False, session=session,
                space=space_of(args))
    topic = topic_name(args.topic)
    type_name = type_of(session, topic, None, space_of(args))
    if "header" not in dict(registry().fields(type_name)):
        node.destroy_node()
        raise UsageError(f"{topic} ({type_name}) has no header.stamp to take a delay from")
    delays: deque[float] = deque(maxlen=args.window)

    def arrived(message: Any) -> None:
        stamp = message.header.stamp
        delays.append(node.get_clock().now().nanoseconds / 1e9 -
                      stamp_seconds(stamp))

    node.create_subscription(type_name, topic, arrived, PROFILES["best_available"])
    shown = 0
    while not node.interrupted:
        node.spin(1.0)
        if not delays or len(delays) == shown and shown == delays.maxlen:
            print("no new messages", flush=True)
            continue
        shown = len(delays)
        values = list(delays)
        mean = sum(values) / len(values)
        spread = (sum((d - mean) ** 2 for d in values) / len(values)) ** 0.5
        print(f"average delay: {mean:.3f}\n\tmin: {min(values):.3f}s max: {max(values):.3f}s "
              f"std dev: {spread:.5f}s window: {len(values)}", flush=True)
    node.destroy_node()
    return 0
