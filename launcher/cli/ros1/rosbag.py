"""`rosbag record | play | info`, as ROS 1's rosbag: `.bag` files (ROS 1's format, which
rosbags and ROS 1's own tools read), `record [-a] [-O NAME.bag | -o PREFIX] [--duration D]
TOPIC…`, `play [-r RATE] [-l] [--clock] [--topics …] FILE.bag`, `info FILE.bag`. A bag of
launcher's rosbag2 (MCAP) converts with `launcher bag convert`."""

from __future__ import annotations

import argparse
import re
import time
from pathlib import Path

from launcher.arguments import Parser
from launcher.errors import LaunchError, UsageError

_DURATION = re.compile(r"^(\d+(?:\.\d*)?)([smh]?)$")


def duration(text: str) -> float:
    """rosbag's --duration: seconds, or with s, m or h (`30`, `5m`, `1.5h`)."""
    match = _DURATION.match(text.strip())
    if not match:
        raise argparse.ArgumentTypeError(f"'{text}' is not a duration (e.g. 30, 30s, 5m, 1h)")
    return float(match.group(1)) * {"": 1, "s": 1, "m": 60, "h": 3600}[match.group(2)]


def parser(prog: str = "rosbag") -> Parser:
    p = Parser(prog=prog, description="rosbag records and plays ROS 1 bags (.bag) on "
                                      "launcher's graph.")
    verbs = p.add_subparsers(dest="verb", metavar="COMMAND", required=True)
    record = verbs.add_parser("record", help="record a bag file with the contents of "
                                             "specified topics")
    record.add_argument("topics", nargs="*", metavar="TOPIC", help="the topics")
    record.add_argument("-a", "--all", action="store_true", help="record all topics")
    record.add_argument("-O", "--output-name", dest="name", metavar="NAME",
                        help="record to bag with name NAME.bag")
    record.add_argument("-o", "--output-prefix", dest="prefix", metavar="PREFIX",
                        help="prepend PREFIX to beginning of bag name")
    record.add_argument("--duration", type=duration, metavar="DURATION",
                        help="record a bag of maximum duration DURATION (30, 30s, 5m, 1h)")
    record.add_argument("-q", "--quiet", action="store_true", help="suppress console output")
    record.set_defaults(run=run_record)
    play = verbs.add_parser("play", help="play back the contents of one bag file")
    play.add_argument("file", metavar="FILE.bag", help="the bag")
    play.add_argument("-r", "--rate", type=float, default=1.0, metavar="FACTOR",
                      help="multiply the publish rate by FACTOR")
    play.add_argument("-l", "--loop", action="store_true", help="loop playback")
    play.add_argument("--clock", action="store_true", help="publish the clock time")
    play.add_argument("--topics", nargs="+", metavar="TOPIC", help="topics to play back")
    play.add_argument("-q", "--quiet", action="store_true", help="suppress console output")
    play.set_defaults(run=run_play)
    info = verbs.add_parser("info", help="summarize the contents of one bag file")
    info.add_argument("file", metavar="FILE.bag", help="the bag")
    info.set_defaults(run=run_info)
    return p


def main(argv: list[str], prog: str = "rosbag") -> int:
    args = parser(prog).parse_args_strictly(argv)
    return int(args.run(args) or 0)


def bag_name(name: str | None, prefix: str | None) -> Path:
    """rosbag's output name: -O NAME (.bag added), or [PREFIX_]YYYY-MM-DD-HH-MM-SS.bag."""
    if name:
        return Path(name if name.endswith(".bag") else f"{name}.bag")
    stamp = time.strftime("%Y-%m-%d-%H-%M-%S")
    return Path(f"{prefix}_{stamp}.bag" if prefix else f"{stamp}.bag")


def run_record(args: argparse.Namespace) -> int:
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


def run_info(args: argparse.Namespace) -> int:
    from launcher.bus import bag1

    print(bag1.info(Path(args.file)))
    return 0


def run_play(args: argparse.Namespace) -> int:
    from launcher.bus import bag, bag1
    from launcher.bus.node import Node

    path = Path(args.file)
    if args.rate <= 0:
        raise UsageError(f"rosbag play: -r must be above 0, got {args.rate:g}")
    if path.suffix != ".bag" and path.is_dir():
        raise LaunchError(f"'{path}' is a rosbag2 bag: play it with `launcher bag play "
                          f"{path}` (or `ros2 bag play`)")
    holder = bag1.temporary_rosbag2(path)
    node = Node("_rosbag_play", argv=[], parameter_services=False)
    try:
        if not args.quiet:
            print(f"[ INFO] Opening {path}", flush=True)
        sent = bag.play(node, Path(holder.name) / "bag", args.rate, args.loop,
                        topics=args.topics, clock=100.0 if args.clock else None)
    except KeyboardInterrupt:
        sent = -1
    finally:
        node.destroy_node()
        holder.cleanup()
    if sent >= 0 and not args.quiet:
        print("\nDone.")
    return 0
