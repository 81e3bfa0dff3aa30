"""`launcher bag record | info | play`: rosbag2 bags in MCAP storage."""

from __future__ import annotations

import argparse
from pathlib import Path

from launcher.bus import bag
from launcher.bus.node import Node
from launcher.cli import positive_number
from launcher.errors import UsageError


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("bag", help="record and play rosbag2 (MCAP) bags")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    record = verbs.add_parser("record", help="record topics to a bag")
    record.add_argument("topics", nargs="*", metavar="TOPIC")
    record.add_argument("-a", "--all", action="store_true", help="every topic")
    record.add_argument("-o", "--output", required=True, metavar="DIR")
    record.add_argument("--duration", type=float, default=None, metavar="SECONDS")
    record.set_defaults(run=run_record)
    info = verbs.add_parser("info", help="what a bag holds")
    info.add_argument("path", metavar="DIR")
    info.set_defaults(run=run_info)
    play = verbs.add_parser("play", help="publish a bag's messages again")
    play.add_argument("path", metavar="DIR")
    play.add_argument("-r", "--rate", type=positive_number, default=1.0)
    play.add_argument("-l", "--loop", action="store_true")
    play.set_defaults(run=run_play)


def run_record(args: argparse.Namespace) -> int:
    if not args.all and not args.topics:
        raise UsageError("name the topics to record, or -a for all of them")
    if Path(args.output).exists():  # before reaching for the bus
        raise UsageError(f"'{args.output}' already exists; choose another output folder")
    node = Node("_launcher_bag_record", argv=[], parameter_services=False)
    topics = [node.resolve(t) for t in args.topics]
    recorder = bag.Recorder(node, Path(args.output), topics, args.all)
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
    node = Node("_launcher_bag_play", argv=[], parameter_services=False)
    try:
        sent = bag.play(node, folder, args.rate, args.loop)
    except KeyboardInterrupt:
        sent = -1
    node.destroy_node()
    if sent >= 0:
        print(f"played {sent} messages")
    return 0
