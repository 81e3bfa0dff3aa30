"""`rostopic pub`: publish data to topic."""

from __future__ import annotations

import argparse

from launcher.bus.names import expand
from launcher.cli import positive_number
from launcher.cli.ros1.values import message_values

LATCH_SECONDS = 3.0  # `pub -1` keeps its latched message up this long, as rostopic does


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic")
    parser.add_argument("type", help="its type, e.g. std_msgs/String")
    parser.add_argument("values", nargs="*", help="the message: YAML, or its fields in order")
    once = parser.add_mutually_exclusive_group()
    once.add_argument("-1", "--once", action="store_true",
                      help="publish one message and exit")
    once.add_argument("-r", "--rate", type=positive_number, metavar="RATE",
                      help="publishing rate (Hz)")
    parser.add_argument("-l", "--latch", action="store_true",
                        help="enable latching for -r (-1 and the default latch already)")


def run(args: argparse.Namespace) -> int:
    from launcher.bus.messages import build
    from launcher.bus.node import Node, Rate
    from launcher.bus.qos import QoS
    from launcher.bus.types import normalize

    type_name = normalize(args.type)
    message = build(type_name, message_values(type_name, args.values))
    latched = args.rate is None or args.latch
    node = Node("_rostopic_pub", argv=[], parameter_services=False)
    qos = QoS(depth=1, transient_local=True) if latched else QoS()
    publisher = node.create_publisher(type_name, expand(args.topic), qos)
    try:
        if args.rate is not None:
            rate = Rate(args.rate)
            while not node.interrupted:
                publisher.publish(message)
                rate.sleep()
        elif args.once:
            print(f"publishing and latching message for {LATCH_SECONDS} seconds", flush=True)
            publisher.publish(message)
            node.spin(LATCH_SECONDS)
        else:
            print("publishing and latching message. Press ctrl-C to terminate", flush=True)
            publisher.publish(message)
            node.spin()
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
    return 0
