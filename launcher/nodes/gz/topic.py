"""`gz topic -l | -i -t T [-d S] | -e -t T [-n N] [-d S] [--json-output] | -t T -m TYPE -p TEXT`.

Unlike Gazebo, `-p` waits (up to a second) for the topic's subscribers before it publishes,
so the one message is not lost to discovery, and `-i` also gives the topic's rate, measured
over a second and a half (`-d S`) with a subscriber of its own (so a lazy sensor runs for it,
as it would for any subscriber)."""

from __future__ import annotations

import json
import threading
import time
from typing import Any

from launcher.arguments import Parser
from launcher.bus import graph, keys
from launcher.bus.messages import MessageError, build, to_data
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.bus.session import open_session
from launcher.errors import LaunchError, UsageError
from launcher.nodes.gz.common import gz_name, message_type, print_names
from launcher.sim import gz_msgs, prototext

RATE_WINDOW = 1.5  # s: `-i` measures the rate over this long


def build_parser() -> Parser:
    """`gz topic`'s command line."""
    parser = Parser(prog="gz topic", description="Gazebo's topics of launcher's sim.",
                     allow_abbrev=False)
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("-l", "--list", action="store_true", help="list the sim's topics")
    mode.add_argument("-i", "--info", action="store_true", help="publishers and subscribers")
    mode.add_argument("-e", "--echo", action="store_true", help="print the messages")
    mode.add_argument("-p", "--pub", metavar="TEXT", help="publish one message (with -m)")
    parser.add_argument("-t", "--topic", metavar="TOPIC", help="the topic (-i, -e, -p)")
    parser.add_argument("-m", "--msgtype", metavar="TYPE", help="e.g. gz.msgs.Twist")
    parser.add_argument("-n", "--num", type=int, default=None, help="-e: stop after N")
    parser.add_argument("-d", "--duration", type=float, default=None,
                        help="-e: stop after S s; -i: measure the rate over S s (1.5)")
    parser.add_argument("--json-output", action="store_true", help="-e: print JSON")
    return parser


def topic(argv: list[str]) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not (args.list or args.info or args.echo or args.pub is not None):
        parser.error("give one of -l, -i, -e or -p")
    if not args.list and not args.topic:
        parser.error("-t TOPIC is required with -i, -e and -p")
    if args.list:
        return _topic_list()
    if args.info:
        return _topic_info(args.topic, RATE_WINDOW if args.duration is None else args.duration)
    if args.echo:
        return _echo(args.topic, args.num, args.duration, args.json_output)
    if not args.msgtype:
        parser.error("-p needs the message type: -m gz.msgs.NAME")
    return _publish(args.topic, args.msgtype, args.pub)


def _sim_topics(session: Any) -> dict[str, graph.TopicInfo]:
    """The topics of the sim's own side (gz-transport's, where Gazebo has them)."""
    return graph.topics(session, keys.SIM)


def _topic_list() -> int:
    return print_names(lambda session: set(_sim_topics(session)))


def _topic_info(name: str, window: float) -> int:
    session = open_session("client")
    try:
        found = [e for e in graph.entities(session, space=keys.SIM) if e.topic == name
                 and e.kind in (keys.PUBLISHER, keys.SUBSCRIPTION)]
        if not found:
            raise LaunchError(f"no publishers or subscribers on topic [{name}]")
        for kind, title in ((keys.PUBLISHER, "Publishers"), (keys.SUBSCRIPTION, "Subscribers")):
            mine = [e for e in found if e.kind == kind]
            if mine:
                print(f"{title} [Node, Message Type]:")
                for entity in sorted(mine, key=lambda e: e.node_fqn):
                    print(f"  {entity.node_fqn}, {gz_name(entity.type_name)}")
            else:
                print(f"No {title.lower()} on topic [{name}]")
        published = sorted({e.type_name for e in found if e.kind == keys.PUBLISHER})
        if published:
            print(_rate(session, name, published[0], window), flush=True)
    finally:
        session.close()
    return 0


def _rate(session: Any, name: str, type_name: str, window: float) -> str:
    """The rate a subscriber gets on `name` over `window` seconds (the bytes, not decoded)."""
    node = Node("_launcher_gz_topic", argv=[], parameter_services=False, session=session,
                space=keys.SIM)
    times: list[float] = []
    node.create_subscription(type_name, name, lambda _: times.append(time.monotonic()),
                             QoS(depth=10), raw=True, inline=True)
    try:
        time.sleep(max(0.0, window))
    finally:
        node.destroy_node()
    if len(times) < 2:
        return f"Rate: {len(times)} message{'' if len(times) == 1 else 's'} in {window:g} s"
    return (f"Rate: {(len(times) - 1) / (times[-1] - times[0]):.3f} Hz "
            f"({len(times)} messages in {window:g} s)")


def _type_of(session: Any, name: str, deadline: float | None) -> str:
    """The sim type published on `name`, waiting for a publisher (until `deadline`)."""
    while True:
        info = _sim_topics(session).get(name)
        if info is not None and info.types:
            return sorted(info.types)[0]
        if deadline is not None and time.monotonic() > deadline:
            raise LaunchError(f"nothing is published on topic [{name}]")
        time.sleep(0.2)


def _echo(name: str, count: int | None, duration: float | None, as_json: bool) -> int:
    session = open_session("client")
    deadline = time.monotonic() + duration if duration is not None else None
    type_name = _type_of(session, name, deadline)
    short = type_name.rsplit("/", 1)[-1]
    node = Node("_launcher_gz_topic", argv=[], parameter_services=False, session=session,
                space=keys.SIM)
    received = [0]
    done = threading.Event()

    def show(message: Any) -> None:
        if done.is_set():
            return
        data = gz_msgs.to_gz(short, to_data(message))
        print(json.dumps(data) if as_json else prototext.format(data), flush=True)
        received[0] += 1
        if count is not None and received[0] >= count:
            done.set()
            node.shutdown()

    node.create_subscription(type_name, name, show, QoS(depth=10))
    try:
        node.spin(None if deadline is None else max(0.0, deadline - time.monotonic()))
    finally:
        node.destroy_node()
    return 0


def parse_message(gz_type: str, text: str, what: str) -> Any:
    """A sim message from Gazebo's text format for `gz_type`; fields are checked."""
    type_name, short = message_type(gz_type)
    data = gz_msgs.to_sim(short, prototext.parse(text, what))
    try:
        return build(type_name, data)
    except MessageError as exc:
        message = exc.message.replace(type_name, gz_type)
        raise UsageError(f"{what}: '{text}' does not fit {gz_type}: {message}") from None


def _publish(name: str, gz_type: str, text: str) -> int:
    message = parse_message(gz_type, text, "-p")
    type_name = message_type(gz_type)[0]
    session = open_session("client")
    info = _sim_topics(session).get(name)
    if info is not None and info.types and type_name not in info.types:
        session.close()
        raise LaunchError(f"topic [{name}] carries {', '.join(map(gz_name, info.types))}, "
                          f"not {gz_type}")
    node = Node("_launcher_gz_topic", argv=[], parameter_services=False, session=session,
                space=keys.SIM)
    try:
        publisher = node.create_publisher(type_name, name, QoS(depth=1))
        deadline = time.monotonic() + 1.0
        while publisher.get_subscription_count() == 0 and time.monotonic() < deadline:
            time.sleep(0.01)
        publisher.publish(message)
        time.sleep(0.05)  # let the message leave before the session closes
    finally:
        node.destroy_node()
    return 0


