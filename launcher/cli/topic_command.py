"""`launcher topic list | echo | pub | hz | bw | delay | info | type | find`, as `ros2 topic`
has them."""

from __future__ import annotations

import argparse
import sys
import threading
import time
from collections import deque
from itertools import pairwise
from typing import TYPE_CHECKING, Any

from launcher.bus import graph, keys
from launcher.bus.names import expand, hidden
from launcher.bus.qos import PROFILES, QoS
from launcher.bus.session import open_session
from launcher.cli import completion, positive_count, positive_number, qos_options
from launcher.errors import LaunchError, UsageError, did_you_mean

if TYPE_CHECKING:
    from launcher.bus.node import Node

# (messages, nodes, YAML and the filter's evaluator are imported by the verbs that use them:
# `topic list`, the most typed, starts in a few tens of milliseconds: bench/commands)


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("topic", help="topics: list, echo, pub, hz, bw, delay, info, type, "
                                          "find")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="the topics on the bus")
    listing.add_argument("-t", "--show-types", action="store_true",
                         help="each topic's message type too")
    listing.add_argument("-v", "--verbose", action="store_true",
                         help="published and subscribed topics, with their types and counts")
    listing.add_argument("--include-hidden-topics", action="store_true",
                         help="also the hidden ones (a name part that begins with '_', as "
                              "actions' /_action/ topics), which ros2 leaves out")
    listing.add_argument("-c", "--count-topics", action="store_true",
                         help="how many topics there are")
    listing.set_defaults(run=run_list)
    kind = verbs.add_parser("type", help="the type of a topic")
    kind.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    kind.set_defaults(run=run_type)
    find = verbs.add_parser("find", help="the topics of a type")
    find.add_argument("type", help="a message type (std_msgs/msg/String)")
    find.set_defaults(run=run_find)
    echo = verbs.add_parser("echo", help="print the messages on a topic")
    echo.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    echo.add_argument("type", nargs="?", help="the message type (default: as published)")
    echo.add_argument("--once", action="store_true", help="print one message and exit")
    echo.add_argument("--field", help="print only this field (a.b.c)")
    echo.add_argument("--csv", action="store_true", help="one comma-separated line each")
    echo.add_argument("--timeout", type=positive_number, default=None, metavar="SECONDS",
                      help="stop after this many seconds; exit 1 if nothing arrived")
    echo.add_argument("--no-arr", action="store_true",
                      help="print arrays and sequences as their type and length")
    echo.add_argument("--no-str", action="store_true", help="print strings as their length")
    echo.add_argument("--flow-style", action="store_true",
                      help="YAML's flow style: each message on one line")
    echo.add_argument("--filter", metavar="EXPR", dest="filter_expr",
                      help="print only messages for which EXPR is true; the message is `m` "
                           "(m.data == 'hi', m.linear.x > 0.5); the same restricted "
                           "expressions as $(eval)")
    echo.add_argument("--raw", action="store_true",
                      help="the serialized message (CDR bytes) instead of its fields")
    length = echo.add_mutually_exclusive_group()
    length.add_argument("-l", "--truncate-length", type=positive_count, default=128,
                        metavar="N", help="cut strings and arrays to N items (default 128)")
    length.add_argument("-f", "--full-length", action="store_true",
                        help="print strings and arrays whole")
    qos_options.add(echo, default="best_available")
    echo.set_defaults(run=run_echo)
    pub = verbs.add_parser("pub", help="publish a message")
    pub.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    pub.add_argument("type", help="its type, e.g. geometry_msgs/msg/Twist")
    pub.add_argument("values", nargs="?", default="{}", help="the message as YAML")
    pub.add_argument("-r", "--rate", type=positive_number, default=1.0,
                     help="messages per second (> 0)")
    pub.add_argument("-1", "--once", action="store_true", help="publish one message and exit")
    pub.add_argument("-t", "--times", type=int, default=0, metavar="N",
                     help="publish N messages and exit (default: until Ctrl-C)")
    pub.add_argument("--latched", action="store_true", help="transient local")
    pub.add_argument("-w", "--wait-matching-subscriptions", type=int, default=None,
                     metavar="N", help="publish once N subscriptions have matched (default: "
                                       "1 with --once or --times, else 0)")
    pub.add_argument("--max-wait-time-secs", type=positive_number, default=None,
                     metavar="SECONDS", help="give up waiting for them after this long "
                                             "(exit 1); default: wait on")
    pub.add_argument("-p", "--print", type=int, default=1, metavar="N",
                     help="print every Nth message published (0: none)")
    pub.add_argument("--keep-alive", type=float, default=0.1, metavar="SECONDS",
                     help="keep the publisher this long after the last message")
    pub.set_defaults(run=run_pub)
    hz = verbs.add_parser("hz", help="the rate of one or more topics, printed every second")
    hz.add_argument("topics", nargs="+", metavar="topic", help="the topics").completer = \
        completion.topics  # type: ignore[attr-defined]
    hz.add_argument("-w", "--window", type=positive_count, default=10000, metavar="N",
                    help="how many of the latest messages the rate is taken over (messages, "
                         "as ROS 2 counts it; default 10000)")
    hz.add_argument("--wall-time", action="store_true",
                    help="accepted: the rate is always taken on the wall clock")
    hz.set_defaults(run=run_hz)
    bw = verbs.add_parser("bw", help="the bandwidth a topic uses, printed every second")
    bw.add_argument("topics", nargs="+", metavar="topic", help="the topics").completer = \
        completion.topics  # type: ignore[attr-defined]
    bw.add_argument("-w", "--window", type=positive_count, default=100, metavar="N",
                    help="how many of the latest messages it is taken over (default 100)")
    bw.set_defaults(run=run_bw)
    delay = verbs.add_parser("delay", help="how old a topic's messages are when they arrive "
                                           "(now - header.stamp), printed every second")
    delay.add_argument("topic", help="the topic (with a header)").completer = completion.topics  # type: ignore[attr-defined]
    delay.add_argument("-w", "--window", type=positive_count, default=10000, metavar="N",
                       help="how many of the latest messages it is taken over (default 10000)")
    delay.add_argument("--use-sim-time", action="store_true",
                       help="now is the simulation's time (/clock), for stamps in sim time")
    delay.set_defaults(run=run_delay)
    info = verbs.add_parser("info", help="type and endpoints of a topic")
    info.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    info.add_argument("-v", "--verbose", action="store_true",
                      help="each publisher and subscription: node, type, QoS")
    info.set_defaults(run=run_info)
    for verb in (listing, echo, pub, hz, bw, delay, info, kind, find):
        verb.add_argument("--sim", action="store_true",
                          help="the simulator's own topics (Gazebo's gz-transport side), not "
                               "the ROS graph's")


def _space(args: argparse.Namespace) -> keys.Space:
    return keys.SIM if args.sim else keys.ROS


def _topic(name: str) -> str:
    return expand(name)


def _type_of(session: Any, topic: str, given: str | None,
             space: keys.Space = keys.ROS) -> str:
    if given:
        return given
    deadline = time.monotonic() + 5.0
    while True:
        table = graph.topics(session, space)
        info = table.get(topic)
        if info and info.publishers:
            return sorted(info.types)[0]
        if time.monotonic() > deadline:
            if info:  # subscribed to, never published: its own name is no suggestion
                hint = f" (it has {len(info.subscribers)} subscriber(s))"
            else:
                hint = did_you_mean(topic, (t for t, i in table.items() if i.publishers))
            raise LaunchError(f"nobody publishes '{topic}'{hint}; give its type to wait for "
                              "it: launcher topic echo TOPIC TYPE")
        time.sleep(0.1)


def run_list(args: argparse.Namespace) -> int:
    session = open_session("client")
    topics = sorted(graph.topics(session, _space(args)).items())
    session.close()
    if not args.include_hidden_topics:
        topics = [(name, info) for name, info in topics if not hidden(name)]
    if args.count_topics:
        print(len(topics))
        return 0
    if args.verbose:  # as `ros2 topic list -v`
        for title, side, noun in (("Published topics:", "publishers", "publisher"),
                                  ("Subscribed topics:", "subscribers", "subscriber")):
            print(title)
            for name, info in topics:
                count = len(getattr(info, side))
                if count:
                    print(f" * {name} [{', '.join(sorted(info.types))}] {count} "
                          f"{noun}{'' if count == 1 else 's'}")
            print()
        return 0
    for name, info in topics:
        print(f"{name} [{', '.join(sorted(info.types))}]" if args.show_types else name)
    return 0


def run_type(args: argparse.Namespace) -> int:
    session = open_session("client")
    topic = _topic(args.topic)
    topics = graph.topics(session, _space(args))
    session.close()
    if topic not in topics:
        raise LaunchError(f"unknown topic '{topic}'{did_you_mean(topic, list(topics))}")
    for name in sorted(topics[topic].types):
        print(name)
    return 0


def run_find(args: argparse.Namespace) -> int:
    session = open_session("client")
    topics = graph.topics(session, _space(args))
    session.close()
    for name, info in sorted(topics.items()):
        if args.type in info.types:
            print(name)
    return 0


def _pick(data: Any, field: str | None) -> Any:
    for part in (field.split(".") if field else []):
        if not isinstance(data, dict) or part not in data:
            raise UsageError(f"--field: no field '{part}'"
                             f"{did_you_mean(part, data if isinstance(data, dict) else [])}")
        data = data[part]
    return data


def _csv(data: Any) -> str:
    if isinstance(data, dict):
        return ",".join(_csv(v) for v in data.values())
    if isinstance(data, list):
        return ",".join(_csv(v) for v in data)
    return str(data)


def run_echo(args: argparse.Namespace) -> int:
    import yaml

    from launcher.bus.node import Node

    accept = _filter(args.filter_expr)
    session = open_session("client")
    topic = _topic(args.topic)
    type_name = _type_of(session, topic, args.type, _space(args))
    node = Node("_launcher_topic_echo", argv=[], parameter_services=False, session=session,
                space=_space(args))
    received = threading.Event()
    shown = echo_options(args)
    shown_count = [0]  # printed so far (rostopic's `-n COUNT` stops at COUNT)

    def show(message: Any) -> None:
        if args.raw:
            text = f"{bytes(message)!r}\n"
        else:
            if accept is not None and not accept(message):
                return
            data = _pick(shown(message, type_name), args.field)
            if args.csv:
                text = _csv(data)
            else:
                text = yaml.safe_dump(data, default_flow_style=args.flow_style,
                                      sort_keys=False, allow_unicode=True,
                                      width=float("inf")) \
                    if isinstance(data, dict | list) else f"{data}\n"
        received.set()
        print(text if args.csv else text + "---", flush=True)
        shown_count[0] += 1
        if args.once or shown_count[0] == getattr(args, "count", 0):
            node.shutdown()

    node.create_subscription(type_name, topic, show, qos_options.chosen(args), raw=args.raw)
    node.spin(args.timeout)
    node.destroy_node()
    if args.timeout is not None and not received.is_set():  # (with or without --once)
        raise LaunchError(f"no message on {topic} within {args.timeout:g} s")
    return 0


def echo_options(args: argparse.Namespace) -> Any:
    """message → printable data, as `--no-arr`, `--no-str` and the truncation say."""
    from launcher.bus.messages import echo_data

    limit = None if args.full_length else args.truncate_length
    return lambda message, type_name: echo_data(message, type_name, limit=limit,
                                                no_arr=args.no_arr, no_str=args.no_str)


def _filter(expression: str | None) -> Any:
    """`--filter EXPR` as a test of a message; the expression is checked before anything
    starts, and a message it fails on is said once and not printed."""
    from launcher.bus.messages import to_data
    from launcher.description.safe_expression import (
        ExpressionError,
        check_expression,
        evaluate,
        fields_of,
    )

    if expression is None:
        return None
    try:
        check_expression(expression, ("m",))
    except ExpressionError as exc:
        raise UsageError(f"--filter: {exc}") from None
    failed: list[str] = []

    def accept(message: Any) -> bool:
        try:
            return bool(evaluate(expression, {"m": fields_of(to_data(message))}))
        except ExpressionError as exc:
            if not failed:
                failed.append(str(exc))
                print(f"--filter: {exc}; such messages are not printed", file=sys.stderr)
            return False

    return accept


def run_pub(args: argparse.Namespace) -> int:
    """As `ros2 topic pub`, its messages printed as rclpy prints them."""
    import yaml

    from launcher.bus.messages import build, ros_repr
    from launcher.bus.node import Node, Rate

    try:
        values = yaml.safe_load(args.values)
    except yaml.YAMLError as exc:
        raise UsageError(f"the message is not valid YAML: {exc}") from None
    message = build(args.type, values)
    node = Node("_launcher_topic_pub", argv=[], parameter_services=False, space=_space(args))
    qos = QoS(depth=1, transient_local=True) if args.latched else QoS()
    topic = _topic(args.topic)
    publisher = node.create_publisher(args.type, topic, qos)
    count = 1 if args.once else args.times
    wanted = args.wait_matching_subscriptions
    if wanted is None:
        wanted = 1 if count > 0 else 0
    try:
        if not _wait_for_subscriptions(node, publisher, wanted, args.max_wait_time_secs):
            node.destroy_node()
            raise LaunchError(f"timed out waiting for {wanted} subscription(s) on {topic}: "
                              f"{publisher.get_subscription_count()} matched within "
                              f"{args.max_wait_time_secs:g} s")
        print("publisher: beginning loop", flush=True)
        rate = Rate(args.rate)
        sent = 0
        while count <= 0 or sent < count:
            publisher.publish(message)
            sent += 1
            if args.print > 0 and sent % args.print == 0:
                print(f"publishing #{sent}: {ros_repr(message)}\n", flush=True)
            if count <= 0 or sent < count:
                rate.sleep()
        if args.latched:
            node.spin()
        elif args.keep_alive > 0:
            node.spin(args.keep_alive)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    return 0


def _wait_for_subscriptions(node: Node, publisher: Any, wanted: int,
                            limit: float | None) -> bool:
    """Until `wanted` subscriptions have matched (False: `limit` seconds went by first).
    With none wanted, a moment for the graph to see the publisher."""
    if wanted <= 0:
        time.sleep(0.2)
        return True
    deadline = None if limit is None else time.monotonic() + limit
    if publisher.get_subscription_count() < wanted:
        print(f"Waiting for at least {wanted} matching subscription(s)...", flush=True)
    while publisher.get_subscription_count() < wanted:
        if deadline is not None and time.monotonic() > deadline:
            return False
        node.spin(0.05)
        if node.interrupted:
            raise KeyboardInterrupt
    return True


def run_hz(args: argparse.Namespace) -> int:
    """As `ros2 topic hz`: every second, each topic's rate over its last `--window` messages,
    with the shortest and longest gap and their spread."""
    from launcher.bus.node import Node

    session = open_session("client")
    node = Node("_launcher_topic_hz", argv=[], parameter_services=False, session=session,
                space=_space(args))
    topics = [_topic(t) for t in args.topics]
    stamps: dict[str, deque[float]] = {t: deque(maxlen=args.window + 1) for t in topics}
    for topic in topics:
        node.create_subscription(_type_of(session, topic, None, _space(args)), topic,
                                 lambda _m, kept=stamps[topic]: kept.append(time.monotonic()),
                                 raw=True)
    printed = dict.fromkeys(topics, 0.0)
    while not node.interrupted:
        node.spin(1.0)
        for topic in topics:
            kept = stamps[topic]
            if len(topics) > 1:
                print(f"{topic}:")
            if len(kept) < 2 or kept[-1] == printed[topic]:
                print("no new messages", flush=True)
                continue
            printed[topic] = kept[-1]
            print(rate_lines(list(kept)), flush=True)
    node.destroy_node()
    return 0


def rate_lines(stamps: list[float]) -> str:
    """`ros2 topic hz`'s two lines for the arrival times `stamps` (seconds)."""
    gaps = [b - a for a, b in pairwise(stamps)]
    mean = sum(gaps) / len(gaps)
    spread = (sum((g - mean) ** 2 for g in gaps) / len(gaps)) ** 0.5
    rate = 1.0 / mean if mean > 0 else 0.0
    return (f"average rate: {rate:.3f}\n\tmin: {min(gaps):.3f}s max: {max(gaps):.3f}s "
            f"std dev: {spread:.5f}s window: {len(stamps)}")


def run_bw(args: argparse.Namespace) -> int:
    """As `ros2 topic bw`: every second, bytes per second over the last `--window` messages,
    and the messages' sizes."""
    from launcher.bus.node import Node

    session = open_session("client")
    node = Node("_launcher_topic_bw", argv=[], parameter_services=False, session=session,
                space=_space(args))
    topics = [_topic(t) for t in args.topics]
    kept: dict[str, deque[tuple[float, int]]] = {t: deque(maxlen=args.window) for t in topics}
    for topic in topics:
        node.create_subscription(
            _type_of(session, topic, None, _space(args)), topic,
            lambda m, into=kept[topic]: into.append((time.monotonic(), len(m))), raw=True)
        print(f"Subscribed to [{topic}]", flush=True)
    while not node.interrupted:
        node.spin(1.0)
        for topic in topics:
            if len(topics) > 1:
                print(f"{topic}:")
            print(bandwidth_lines(list(kept[topic]), time.monotonic()), flush=True)
    node.destroy_node()
    return 0


def _size(count: float) -> str:
    for unit, scale in (("MB", 1e6), ("KB", 1e3)):
        if count >= scale:
            return f"{count / scale:.2f} {unit}"
    return f"{count:.0f} B"


def bandwidth_lines(samples: list[tuple[float, int]], now: float) -> str:
    """`ros2 topic bw`'s lines for (arrival time, size) samples."""
    if len(samples) < 2:
        return "no new messages" if not samples else "waiting for a second message"
    sizes = [size for _, size in samples]
    span = max(now - samples[0][0], 1e-9)
    return (f"{_size(sum(sizes) / span)}/s from {len(sizes)} messages\n"
            f"\tMessage size mean: {_size(sum(sizes) / len(sizes))} min: {_size(min(sizes))} "
            f"max: {_size(max(sizes))}")


def run_delay(args: argparse.Namespace) -> int:
    """As `ros2 topic delay`: every second, how old messages are on arrival (their
    header.stamp against now), over the last `--window` messages."""
    from launcher.bus.node import Node
    from launcher.bus.types import registry

    session = open_session("client")
    argv = ["--ros-args", "-p", "use_sim_time:=true"] if args.use_sim_time else []
    node = Node("_launcher_topic_delay", argv=argv, parameter_services=False, session=session,
                space=_space(args))
    topic = _topic(args.topic)
    type_name = _type_of(session, topic, None, _space(args))
    if "header" not in dict(registry().fields(type_name)):
        node.destroy_node()
        raise UsageError(f"{topic} ({type_name}) has no header.stamp to take a delay from")
    delays: deque[float] = deque(maxlen=args.window)

    def arrived(message: Any) -> None:
        stamp = message.header.stamp
        delays.append(node.get_clock().now().nanoseconds / 1e9 -
                      (stamp.sec + stamp.nanosec / 1e9))

    node.create_subscription(type_name, topic, arrived, PROFILES["best_available"])
    shown = 0
    while not node.interrupted:
        node.spin(1.0)
        if not delays or len(delays) == shown and shown == delays.maxlen:
            print("no new messages", flush=True)
            continue
        shown = len(delays)
        values = list(delays)
        mean = sum(values) / len(values)
        spread = (sum((d - mean) ** 2 for d in values) / len(values)) ** 0.5
        print(f"average delay: {mean:.3f}\n\tmin: {min(values):.3f}s max: {max(values):.3f}s "
              f"std dev: {spread:.5f}s window: {len(values)}", flush=True)
    node.destroy_node()
    return 0


def run_info(args: argparse.Namespace) -> int:
    """As `ros2 topic info [-v]`: the type, the counts, and with -v each endpoint with its QoS
    in ros2's layout."""
    session = open_session("client")
    topic = _topic(args.topic)
    info = graph.topics(session, _space(args)).get(topic)
    session.close()
    if info is None:
        raise LaunchError(f"unknown topic '{topic}'")
    print(f"Type: {', '.join(sorted(info.types))}")
    for title, endpoints in (("Publisher", info.publishers),
                             ("Subscription", info.subscribers)):
        if args.verbose:
            print()
        print(f"{title} count: {len(endpoints)}")
        if args.verbose:
            for entity in sorted(endpoints, key=lambda e: e.node_fqn):
                print()
                print(endpoint_lines(entity, title.upper()))
    return 0


def endpoint_lines(entity: Any, kind: str) -> str:
    """One endpoint as `ros2 topic info -v` prints it."""
    qos = QoS.from_key(entity.qos)
    lines = [f"Node name: {entity.node}", f"Node namespace: {entity.namespace or '/'}",
             f"Topic type: {entity.type_name}", f"Topic type hash: {entity.type_hash}",
             f"Endpoint type: {kind}", f"GID: {entity.zid}.{entity.node_id}.{entity.entity_id}",
             "QoS profile:"]
    if qos is None:
        return "\n".join([*lines, "  (not announced)"])
    return "\n".join([
        *lines,
        f"  Reliability: {qos.reliability_name}",
        f"  History (Depth): KEEP_LAST ({qos.depth})",
        f"  Durability: {qos.durability_name}",
        "  Lifespan: Infinite", "  Deadline: Infinite", "  Liveliness: AUTOMATIC",
        "  Liveliness lease duration: Infinite"])
