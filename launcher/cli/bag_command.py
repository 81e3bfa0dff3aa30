"""`launcher bag record | info | play | list`: rosbag2 bags (MCAP or SQLite), as `ros2 bag`
has them; ROS 1's `rosbag record -O name.bag --duration=60` is taken too, with a note."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from launcher.bus import bag
from launcher.bus.node import Node
from launcher.cli import positive_count, positive_number
from launcher.errors import UsageError


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("bag", help="record and play rosbag2 bags (MCAP or SQLite)")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    record = verbs.add_parser("record", help="record topics to a bag")
    record.add_argument("topics", nargs="*", metavar="TOPIC", help="the topics to record (or -a)")
    record.add_argument("--topics", nargs="+", dest="more_topics", default=[], metavar="TOPIC",
                        help="topics to record (as the positional ones)")
    record.add_argument("-a", "--all", action="store_true", help="every topic")
    record.add_argument("-o", "--output", metavar="DIR",
                        help="the bag's folder (default: rosbag2_YYYY_MM_DD-HH_MM_SS)")
    record.add_argument("-O", dest="ros1_output", metavar="NAME.bag",
                        help="ROS 1's rosbag option: the bag is the folder NAME")
    record.add_argument("-s", "--storage", choices=sorted(bag.STORAGES), default="mcap",
                        help="storage format (default mcap)")
    record.add_argument("-d", "--max-bag-duration", type=positive_number, metavar="SECONDS",
                        help="start a new file after this many seconds")
    record.add_argument("-b", "--max-bag-size", type=positive_count, metavar="BYTES",
                        help="start a new file after this many bytes of messages")
    record.add_argument("--qos-profile-overrides-path", metavar="FILE",
                        help="a YAML file of topic: {reliability, durability, history, depth} "
                             "to subscribe with")
    record.add_argument("--duration", type=positive_number, default=None, metavar="SECONDS",
                        help="stop recording after this many seconds (ROS 1's rosbag option)")
    record.set_defaults(run=run_record)
    info = verbs.add_parser("info", help="what a bag holds")
    info.add_argument("path", metavar="DIR", help="the bag (a folder)")
    info.set_defaults(run=run_info)
    play = verbs.add_parser("play", help="publish a bag's messages again")
    play.add_argument("path", metavar="DIR", help="the bag (a folder)")
    play.add_argument("--topics", nargs="+", metavar="TOPIC", help="only these topics")
    play.add_argument("-r", "--rate", type=positive_number, default=1.0, metavar="FACTOR",
                      help="how many times faster than recorded (default 1)")
    play.add_argument("-l", "--loop", action="store_true", help="play again from the start, "
                                                                "until Ctrl-C")
    play.add_argument("--clock", type=positive_number, nargs="?", const=40.0, default=None,
                      metavar="HZ", help="publish /clock from the bag's time, HZ times a second "
                                         "(default 40)")
    play.add_argument("-p", "--start-paused", action="store_true",
                      help="start paused; Enter plays and pauses")
    play.add_argument("--start-offset", type=float, default=0.0, metavar="SECONDS",
                      help="skip this many seconds from the bag's start")
    play.set_defaults(run=run_play)
    convert = verbs.add_parser("convert", help="a ROS 1 bag (.bag) to a rosbag2 bag (MCAP), "
                                               "or back")
    convert.add_argument("source", metavar="IN", help="a .bag file, or a rosbag2 bag folder")
    convert.add_argument("target", metavar="OUT",
                         help="the new rosbag2 folder, or the new .bag file")
    convert.set_defaults(run=run_convert)
    listing = verbs.add_parser("list", help="the storage formats (or converters, "
                                            "compressors) bags can use")
    listing.add_argument("plugin", nargs="?", default="storage",
                         choices=("storage", "converter", "compressor"),
                         help="which kind of plugin to list (default storage)")
    listing.set_defaults(run=run_list)


def run_record(args: argparse.Namespace) -> int:
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


def _bag(path: str) -> Path:
    folder = Path(path)
    if not (folder / "metadata.yaml").is_file():
        raise UsageError(f"'{path}' is not a bag (no metadata.yaml)")
    return folder


def run_info(args: argparse.Namespace) -> int:
    print(bag.describe(_bag(args.path)))
    return 0


def run_play(args: argparse.Namespace) -> int:
    folder = _bag(args.path)
    if args.start_offset < 0:
        raise UsageError(f"--start-offset: expected seconds ≥ 0, got {args.start_offset:g}")
    node = Node("_launcher_bag_play", argv=[], parameter_services=False)
    try:
        sent = bag.play(node, folder, args.rate, args.loop, topics=args.topics,
                        clock=args.clock, paused=args.start_paused, offset=args.start_offset)
    except KeyboardInterrupt:
        sent = -1
    finally:
        node.destroy_node()
    if sent >= 0:
        print(f"played {sent} messages")
    return 0


def run_convert(args: argparse.Namespace) -> int:
    from launcher.bus import bag1

    bag1.convert(Path(args.source), Path(args.target))
    print(f"wrote {args.target}")
    return 0


def run_list(args: argparse.Namespace) -> int:
    """As `ros2 bag list PLUGIN`."""
    names = {"storage": sorted(bag.STORAGES), "converter": ["cdr"], "compressor": ["zstd"]}
    print("\n".join(names[args.plugin]))
    return 0
