"""`rostopic list | echo | pub | hz | bw | info | type`, as ROS 1's rostopic: its flags, its
type names (`std_msgs/String`), `echo /topic/field`, and `pub`'s positional values and its
latching (without `-1` or `-r` it publishes once, latches, and stays until Ctrl-C)."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from launcher.arguments import Parser
from launcher.bus import graph
from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import expand
from launcher.bus.session import open_session
from launcher.cli import positive_number
from launcher.errors import LaunchError, UsageError, did_you_mean

LATCH_SECONDS = 3.0  # `pub -1` keeps its latched message up this long, as rostopic does


def parser(prog: str = "rostopic") -> Parser:
    p = Parser(prog=prog, description="rostopic is a command-line tool for printing "
                                      "information about ROS Topics.")
    verbs = p.add_subparsers(dest="verb", metavar="COMMAND", required=True)
    listing = verbs.add_parser("list", help="list active topics")
    listing.add_argument("-v", "--verbose", action="store_true",
                         help="list full details about each topic")
    listing.add_argument("namespace", nargs="?", help="only topics below this namespace")
    listing.set_defaults(run=run_list)
    echo = verbs.add_parser("echo", help="print messages to screen")
    echo.add_argument("topic", help="the topic, or /topic/field")
    echo.add_argument("-n", dest="count", type=int, default=0, metavar="COUNT",
                      help="number of messages to echo")
    echo.add_argument("--noarr", action="store_true", help="exclude arrays")
    echo.add_argument("--nostr", action="store_true", help="exclude strings")
    echo.add_argument("-p", dest="plot", action="store_true",
                      help="echo in a plotting friendly format (comma separated)")
    echo.add_argument("--filter", dest="filter_expr", metavar="FILTER-EXPRESSION",
                      help="python expression to filter messages that are printed, with the "
                           "message as m")
    echo.set_defaults(run=run_echo)
    pub = verbs.add_parser("pub", help="publish data to topic")
    pub.add_argument("topic", help="the topic")
    pub.add_argument("type", help="its type, e.g. std_msgs/String")
    pub.add_argument("values", nargs="*", help="the message: YAML, or its fields in order")
    once = pub.add_mutually_exclusive_group()
    once.add_argument("-1", "--once", action="store_true",
                      help="publish one message and exit")
    once.add_argument("-r", "--rate", type=positive_number, metavar="RATE",
                      help="publishing rate (hz)")
    pub.add_argument("-l", "--latch", action="store_true",
                     help="enable latching for -r (-1 and the default latch already)")
    pub.set_defaults(run=run_pub)
    for verb, text in (("hz", "display publishing rate of topic"),
                       ("bw", "display bandwidth used by topic")):
        rate = verbs.add_parser(verb, help=text)
        rate.add_argument("topics", nargs="+", metavar="topic", help="the topics")
        rate.add_argument("-w", "--window", type=int, default=None, metavar="WINDOW",
                          help="window size, in # of messages, for calculating rate")
        rate.set_defaults(run=run_rate)
    info = verbs.add_parser("info", help="print information about active topic")
    info.add_argument("topic", help="the topic")
    info.set_defaults(run=run_info)
    kind = verbs.add_parser("type", help="print topic or field type")
    kind.add_argument("topic", help="the topic")
    kind.set_defaults(run=run_type)
    return p


def main(argv: list[str], prog: str = "rostopic") -> int:
    args = parser(prog).parse_args_strictly(argv)
    return int(args.run(args) or 0)


def _topics() -> dict[str, graph.TopicInfo]:
    session = open_session("client")
    try:
        return graph.topics(session)
    finally:
        session.close()


def _published(topic: str, topics: dict[str, graph.TopicInfo]) -> graph.TopicInfo:
    info = topics.get(topic)
    if info is None:
        raise LaunchError(f"unknown topic '{topic}'{did_you_mean(topic, topics)}")
    return info


def run_list(args: argparse.Namespace) -> int:
    below = expand(args.namespace).rstrip("/") + "/" if args.namespace else "/"
    topics = {n: i for n, i in sorted(_topics().items()) if n.startswith(below)}
    if not args.verbose:
        for name in topics:
            print(name)
        return 0
    for title, side, noun in (("Published topics:", "publishers", "publisher"),
                              ("Subscribed topics:", "subscribers", "subscriber")):
        print(title)
        for name, info in topics.items():
            count = len(getattr(info, side))
            if count:
                kinds = ", ".join(ros1_spelling(t) for t in sorted(info.types))
                print(f" * {name} [{kinds}] {count} {noun}{'' if count == 1 else 's'}")
        print()
    return 0


def split_field(name: str, topics: dict[str, Any]) -> tuple[str, str | None]:
    """`/odom/pose/pose` → ('/odom', 'pose.pose') when /odom is a topic and the whole is not,
    as rostopic reads `echo /topic/field`."""
    if name in topics:
        return name, None
    parts = name.split("/")
    for cut in range(len(parts) - 1, 1, -1):
        head = "/".join(parts[:cut])
        if head in topics:
            return head, ".".join(parts[cut:])
    return name, None


def run_echo(args: argparse.Namespace) -> int:
    from launcher.cli import topic_command

    wanted = expand(args.topic)
    topics = _topics()
    topic, field = split_field(wanted, topics)
    info = topics.get(topic)
    if info is None or not info.publishers:  # (on stderr, as rostopic writes it)
        print(f"WARNING: topic [{wanted}] does not appear to be published yet",
              file=sys.stderr, flush=True)
    echo = argparse.Namespace(
        topic=topic, type=None, once=args.count == 1, count=args.count, field=field,
        csv=args.plot, timeout=None, no_arr=args.noarr, no_str=args.nostr, flow_style=False,
        filter_expr=args.filter_expr, raw=False, truncate_length=128, full_length=True,
        sim=False, qos_profile="best_available", qos_depth=None, qos_history=None,
        qos_reliability=None, qos_durability=None)
    if info is not None and info.publishers:
        return topic_command.run_echo(echo)
    return _echo_when_published(echo)


def _echo_when_published(echo: argparse.Namespace) -> int:
    """rostopic waits for a topic nobody publishes yet: so do we, until it has a type."""
    from launcher.cli import topic_command

    while True:
        info = _topics().get(echo.topic)
        if info is not None and info.publishers:
            return topic_command.run_echo(echo)
        time.sleep(0.5)


def message_values(type_name: str, words: list[str]) -> Any:
    """The message rostopic pub builds from its words: one YAML mapping, or values for the
    fields in their order (`rostopic pub /c std_msgs/String hello`)."""
    import yaml

    from launcher.bus.messages import build, to_data

    loaded = []
    for word in words:
        try:
            loaded.append(yaml.safe_load(word))
        except yaml.YAMLError as exc:
            raise UsageError(f"Argument error: the value '{word}' is not valid YAML: "
                             f"{' '.join(str(exc).split())}") from None
    if not loaded:
        return {}
    if len(loaded) == 1 and (loaded[0] is None or isinstance(loaded[0], dict)):
        return loaded[0] or {}
    fields = list(to_data(build(type_name, {})))
    if len(loaded) > len(fields):
        raise UsageError(f"Argument error: too many arguments: {type_name} has "
                         f"{len(fields)} field(s) ({', '.join(fields)}), {len(loaded)} given")
    return dict(zip(fields, loaded, strict=False))


def run_pub(args: argparse.Namespace) -> int:
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


def run_rate(args: argparse.Namespace) -> int:
    from launcher.cli import topic_command

    if args.verb == "hz":
        for topic in args.topics:
            print(f"subscribed to [{expand(topic)}]", flush=True)
    rate = argparse.Namespace(topics=[expand(t) for t in args.topics], wall_time=False,
                              window=args.window or (10000 if args.verb == "hz" else 100),
                              sim=False)
    return (topic_command.run_hz if args.verb == "hz" else topic_command.run_bw)(rate)


def run_info(args: argparse.Namespace) -> int:
    topic = expand(args.topic)
    info = _published(topic, _topics())
    print(f"Type: {', '.join(ros1_spelling(t) for t in sorted(info.types))}\n")
    for title, endpoints in (("Publishers", info.publishers),
                             ("Subscribers", info.subscribers)):
        print(f"{title}: ")
        names = sorted({e.node_fqn for e in endpoints if not e.node.startswith("_")})
        for name in names:
            print(f" * {name}")
        if not names:
            print(" None")
        print()
    return 0


def run_type(args: argparse.Namespace) -> int:
    wanted = expand(args.topic)
    topics = _topics()
    topic, _field = split_field(wanted, topics)
    info = _published(topic, topics)
    for name in sorted(info.types):
        print(ros1_spelling(name))
    return 0
