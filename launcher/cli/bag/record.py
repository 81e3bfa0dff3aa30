"""`launcher bag record`: record topics to a bag."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from launcher.bus import bag
from launcher.bus.node import Node
from launcher.cli import positive_count, positive_number
from launcher.errors import UsageError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="*", metavar="TOPIC", help="the topics to record (or -a)")
    parser.add_argument("--topics", nargs="+", dest="more_topics", default=[], metavar="TOPIC",
                        help="topics to record (as the positional ones)")
    parser.add_argument("-a", "--all", action="store_true", help="every topic")
    parser.add_argument("-o", "--output", metavar="DIR",
                        help="the bag's folder (default: rosbag2_YYYY_MM_DD-HH_MM_SS)")
    parser.add_argument("-O", dest="ros1_output", metavar="NAME.bag",
                        help="ROS 1's rosbag option: the bag is the folder NAME")
    parser.add_argument("-s", "--storage", choices=sorted(bag.STORAGES), default="mcap",
                        help="storage format (default mcap)")
    parser.add_argument("-d", "--max-bag-duration", type=positive_number, metavar="SECONDS",
                        help="start a new file after this many seconds")
    parser.add_argument("-b", "--max-bag-size", type=positive_count, metavar="BYTES",
                        help="start a new file after this many bytes of messages")
    parser.add_argument("--qos-profile-overrides-path", metavar="FILE",
                        help="a YAML file of topic: {reliability, durability, history, depth} "
                             "to subscribe with")
    parser.add_argument("--duration", type=positive_number, default=None, metavar="SECONDS",
                        help="stop recording after this many seconds (ROS 1's rosbag option)")


def run(args: argparse.Namespace) -> int:
    topics = [*args.topics, *args.more_topics]
    if not args.all and not topics:
        raise UsageError("name the topics to record, or -a for all of them")
    output = args.output
    if args.ros1_output:
        if output:
            raise UsageError("give either -o or -O (ROS 1's), not both")
        output = args.ros1_output.removesuffix(".bag")
        print(f"note: -O is ROS 1's rosbag option; a ROS 2 bag is a folder: writing "
              f"'{output}/'", file=sys.stderr)
    if args.duration is not None:
        print(f"note: --duration is ROS 1's rosbag option; recording stops after "
              f"{args.duration:g} s (-d/--max-bag-duration splits the bag instead)",
              file=sys.stderr)
    output = output or time.strftime("rosbag2_%Y_%m_%d-%H_%M_%S")
    if Path(output).exists():  # before reaching for the bus
        raise UsageError(f"'{output}' already exists; choose another output folder")
    overrides = bag.load_qos_overrides(args.qos_profile_overrides_path) \
        if args.qos_profile_overrides_path else {}
    node = Node("_launcher_bag_record", argv=[], parameter_services=False)
    writer = bag.BagWriter(Path(output), args.storage,
                           None if args.max_bag_duration is None else
                           int(args.max_bag_duration * 1e9), args.max_bag_size)
    recorder = bag.Recorder(node, writer, [node.resolve(t) for t in topics], args.all,
                            {node.resolve(t): q for t, q in overrides.items()})
    recorder.run(args.duration)
    node.destroy_node()
    for topic, count in sorted(recorder.counts.items()):
        print(f"recorded {count} messages on {topic}")
    return 0
