"""`launcher topic pub`: publish a message."""

from __future__ import annotations

import argparse
import time
from typing import TYPE_CHECKING, Any

from launcher.bus.qos import QoS
from launcher.cli import completion, positive_number
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.message_text import message_from
from launcher.cli.topic.lookup import topic_name
from launcher.errors import LaunchError

if TYPE_CHECKING:
    from launcher.bus.node import Node


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    parser.add_argument("type", help="its type, e.g. geometry_msgs/msg/Twist")
    parser.add_argument("values", nargs="?", default="{}", help="the message as YAML")
    parser.add_argument("-r", "--rate", type=positive_number, default=1.0,
                        help="messages per second (> 0)")
    parser.add_argument("-1", "--once", action="store_true", help="publish one message and exit")
    parser.add_argument("-t", "--times", type=int, default=0, metavar="N",
                        help="publish N messages and exit (default: until Ctrl-C)")
    parser.add_argument("--latched", action="store_true", help="transient local")
    parser.add_argument("-w", "--wait-matching-subscriptions", type=int, default=None,
                        metavar="N", help="publish once N subscriptions have matched (default: "
                                          "1 with --once or --times, else 0)")
    parser.add_argument("--max-wait-time-secs", type=positive_number, default=None,
                        metavar="SECONDS", help="give up waiting for them after this long "
                                                "(exit 1); default: wait on")
    parser.add_argument("-p", "--print", type=int, default=1, metavar="N",
                        help="print every Nth message published (0: none)")
    parser.add_argument("--keep-alive", type=float, default=0.1, metavar="SECONDS",
                        help="keep the publisher this long after the last message")
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    """As `ros2 topic pub`, its messages printed as rclpy prints them."""

    from launcher.bus.messages import ros_repr
    from launcher.bus.node import Node, Rate

    message = message_from(args.type, args.values, "message")
    node = Node("_launcher_topic_pub", argv=[], parameter_services=False, space=space_of(args))
    qos = QoS(depth=1, transient_local=True) if args.latched else QoS()
    topic = topic_name(args.topic)
    publisher = node.create_publisher(args.type, topic, qos)
    count = 1 if args.once else args.times
    wanted = args.wait_matching_subscriptions
    if wanted is None:
        wanted = 1 if count > 0 else 0
    try:
        if not _wait_for_subscriptions(node, publisher, wanted, args.max_wait_time_secs):
            node.destroy_node()
            raise LaunchError(f"timed out waiting for {wanted} subscription(s) on {topic}: "
                              f"{publisher.get_subscription_count()} matched within "
                              f"{args.max_wait_time_secs:g} s")
        print("publisher: beginning loop", flush=True)
        rate = Rate(args.rate)
        sent = 0
        while count <= 0 or sent < count:
            publisher.publish(message)
            sent += 1
            if args.print > 0 and sent % args.print == 0:
                print(f"publishing #{sent}: {ros_repr(message)}\n", flush=True)
            if count <= 0 or sent < count:
                rate.sleep()
        if args.latched:
            node.spin()
        elif args.keep_alive > 0:
            node.spin(args.keep_alive)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    return 0


def _wait_for_subscriptions(node: Node, publisher: Any, wanted: int,
                            limit: float | None) -> bool:
    """Until `wanted` subscriptions have matched (False: `limit` seconds went by first).
    With none wanted, a moment for the graph to see the publisher."""
    if wanted <= 0:
        time.sleep(0.2)
        return True
    deadline = None if limit is None else time.monotonic() + limit
    if publisher.get_subscription_count() < wanted:
        print(f"Waiting for at least {wanted} matching subscription(s)...", flush=True)
    while publisher.get_subscription_count() < wanted:
        if deadline is not None and time.monotonic() > deadline:
            return False
        node.spin(0.05)
        if node.interrupted:
            raise KeyboardInterrupt
    return True
