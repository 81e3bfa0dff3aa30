"""`rostopic type`: print topic or field type."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import expand
from launcher.cli.ros1.rostopic.lookup import published_topic, split_field, topic_table


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic")


def run(args: argparse.Namespace) -> int:
    wanted = expand(args.topic)
    topics = topic_table()
    topic, _field = split_field(wanted, topics)
    info = published_topic(topic, topics)
    for name in sorted(info.types):
        print(ros1_spelling(name))
    return 0
