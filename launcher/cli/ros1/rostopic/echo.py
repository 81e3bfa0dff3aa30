"""`rostopic echo`: print messages to screen."""

from __future__ import annotations

import argparse
import sys
import time

from launcher.bus.names import expand
from launcher.cli.ros1.rostopic.lookup import split_field, topic_table


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic, or /topic/field")
    parser.add_argument("-n", dest="count", type=int, default=0, metavar="COUNT",
                        help="number of messages to echo")
    parser.add_argument("--noarr", action="store_true", help="exclude arrays")
    parser.add_argument("--nostr", action="store_true", help="exclude strings")
    parser.add_argument("-p", dest="plot", action="store_true",
                        help="echo in a plotting friendly format (comma separated)")
    parser.add_argument("--filter", dest="filter_expr", metavar="FILTER-EXPRESSION",
                        help="python expression to filter messages that are printed, with the "
                             "message as m")


def run(args: argparse.Namespace) -> int:
    from launcher.cli.topic import echo

    wanted = expand(args.topic)
    topics = topic_table()
    topic, field = split_field(wanted, topics)
    info = topics.get(topic)
    if info is None or not info.publishers:  # (on stderr, as rostopic writes it)
        print(f"WARNING: topic [{wanted}] does not appear to be published yet",
              file=sys.stderr, flush=True)
    options = argparse.Namespace(
        topic=topic, type=None, once=args.count == 1, count=args.count, field=field,
        csv=args.plot, timeout=None, no_arr=args.noarr, no_str=args.nostr, flow_style=False,
        filter_expr=args.filter_expr, raw=False, truncate_length=128, full_length=True,
        sim=False, qos_profile="best_available", qos_depth=None, qos_history=None,
        qos_reliability=None, qos_durability=None)
    if info is not None and info.publishers:
        return echo.run(options)
    return _echo_when_published(options)


def _echo_when_published(options: argparse.Namespace) -> int:
    """rostopic waits for a topic nobody publishes yet: so do we, until it has a type."""
    from launcher.cli.topic import echo

    while True:
        info = topic_table().get(options.topic)
        if info is not None and info.publishers:
            return echo.run(options)
        time.sleep(0.5)
