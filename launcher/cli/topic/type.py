"""`launcher topic type`: the type of a topic."""

from __future__ import annotations

import argparse

from launcher.bus import graph
from launcher.bus.session import open_session
from launcher.cli import completion
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.topic.lookup import topic_name
from launcher.errors import LaunchError, did_you_mean


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    add_sim_option(parser, "topics")


def run(args: argparse.Namespace) -> int:
    session = open_session("client")
    topic = topic_name(args.topic)
    topics = graph.topics(session, space_of(args))
    session.close()
    if topic not in topics:
        raise LaunchError(f"unknown topic '{topic}'{did_you_mean(topic, list(topics))}")
    for name in sorted(topics[topic].types):
        print(name)
    return 0
