"""`rosbag record`: record a bag file with the contents of specified topics."""

from __future__ import annotations

import argparse
import re
import time
from pathlib import Path

from launcher.errors import UsageError

_DURATION = re.compile(r"^(\d+(?:\.\d*)?)([smh]?)$")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topics", nargs="*", metavar="TOPIC", help="the topics")
    parser.add_argument("-a", "--all", action="store_true", help="record all topics")
    parser.add_argument("-O", "--output-name", dest="name", metavar="NAME",
                        help="record to bag with name NAME.bag")
    parser.add_argument("-o", "--output-prefix", dest="prefix", metavar="PREFIX",
                        help="prepend PREFIX to beginning of bag name")
    parser.add_argument("--duration", type=duration, metavar="DURATION",
                        help="record a bag of maximum duration DURATION (30, 30s, 5m, 1h)")
    parser.add_argument("-q", "--quiet", action="store_true", help="suppress console output")


def duration(text: str) -> float:
    """rosbag's --duration: seconds, or with s, m or h (`30`, `5m`, `1.5h`)."""
    match = _DURATION.match(text.strip())
    if not match:
        raise argparse.ArgumentTypeError(f"'{text}' is not a duration (e.g. 30, 30s, 5m, 1h)")
    return float(match.group(1)) * {"": 1, "s": 1, "m": 60, "h": 3600}[match.group(2)]


def bag_name(name: str | None, prefix: str | None) -> Path:
    """rosbag's output name: -O NAME (.bag added), or [PREFIX_]YYYY-MM-DD-HH-MM-SS.bag."""
    if name:
        return Path(name if name.endswith(".bag") else f"{name}.bag")
    stamp = time.strftime("%Y-%m-%d-%H-%M-%S")
    return Path(f"{prefix}_{stamp}.bag" if prefix else f"{stamp}.bag")


def run(args: argparse.Namespace) -> int:
    from launcher.bus import bag, bag1
    from launcher.bus.node import Node

    if not args.all and not args.topics:
        raise UsageError("rosbag record: you must specify a topic name or use the -a option")
    if args.name and args.prefix:
        raise UsageError("rosbag record: give -O or -o, not both")
    path = bag_name(args.name, args.prefix)
    bag1.check_writable(path)  # before anything reaches for the graph
    node = Node("_rosbag_record", argv=[], parameter_services=False)
    try:
        writer = bag1.Bag1Writer(path)
        if not args.quiet:
            print(f"[ INFO] Recording to '{path}'.", flush=True)
        recorder = bag.Recorder(node, writer, [node.resolve(t) for t in args.topics],
                                args.all)
        recorder.run(args.duration)
    finally:
        node.destroy_node()
    if not args.quiet:
        for topic, count in sorted(recorder.counts.items()):
            print(f"[ INFO] recorded {count} messages on {topic}")
    return 0
