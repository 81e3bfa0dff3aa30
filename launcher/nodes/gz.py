"""`gz topic|service|model …`: Gazebo's command line over launcher's sim (`gz sim` is the sim).

  gz topic -l | -i -t T | -e -t T [-n N] [-d S] [--json-output] | -t T -m TYPE -p TEXT
  gz service -l | -i -s S | -s S --reqtype TYPE --reptype TYPE [--timeout MS] --req TEXT
  gz model --list | -m NAME [-p]
Types are Gazebo's names (gz.msgs.Twist, ignition.msgs.Twist); texts are Protocol Buffers'
text format, and `-e` prints messages in it, as Gazebo does. Unlike Gazebo, `-p` waits
(up to a second) for the topic's subscribers before it publishes, so the one message is
not lost to discovery.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import threading
import time
from typing import Any, NoReturn

from launcher.bus import graph, keys
from launcher.bus.messages import MessageError, build, to_data
from launcher.bus.node import Node
from launcher.bus.qos import QoS
from launcher.bus.session import open_session
from launcher.errors import LaunchError, UsageError, did_you_mean
from launcher.nodes import gz_msgs, prototext
from launcher.nodes.conversions import SIM, SIM_MESSAGES, _short, sim_type
from launcher.nodes.create import find_world

VERBS = {"sim": "run a world (launcher's MuJoCo sim)", "topic": "topics of the sim",
         "service": "services of the sim", "model": "models of the running world"}
STATE_TYPE = f"{SIM}/srv/State"


class GzUsage(UsageError):
    exit_code = 2


class _Parser(argparse.ArgumentParser):
    """argparse that raises one clean error, with "did you mean" for a mistyped flag."""

    def error(self, message: str) -> NoReturn:
        hint = ""
        if message.startswith("unrecognized arguments: "):
            flags = [s for a in self._actions for s in a.option_strings]
            words = message.split(": ", 1)[1].split()
            hint = "".join(did_you_mean(w, flags) for w in words if w.startswith("-"))
        raise GzUsage(f"{self.prog}: {message}{hint} (see `{self.prog} -h`)")


def usage() -> str:
    lines = ["usage: gz COMMAND [options]  (launcher's Gazebo commands)", "commands:"]
    lines += [f"  {name:<8} {text}" for name, text in VERBS.items()]
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    if not argv or argv[0] in ("-h", "--help", "help"):
        print(usage())
        return 0
    verb, rest = argv[0], argv[1:]
    if verb in ("--version", "--versions"):
        print("launcher's gz (MuJoCo sim)")
        return 0
    if verb == "sim":
        from launcher.nodes.sim import main as sim

        return sim(rest)
    commands = {"topic": topic, "service": service, "model": model}
    if verb not in commands:
        raise GzUsage(f"gz: unknown command '{verb}'{did_you_mean(verb, list(VERBS))}; "
                      f"commands: {', '.join(VERBS)}")
    return commands[verb](rest)


# --- gz topic ------------------------------------------------------------------------------
def topic(argv: list[str]) -> int:
    parser = _Parser(prog="gz topic", description="Gazebo's topics of launcher's sim.",
                     allow_abbrev=False)
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("-l", "--list", action="store_true", help="list the sim's topics")
    mode.add_argument("-i", "--info", action="store_true", help="publishers and subscribers")
    mode.add_argument("-e", "--echo", action="store_true", help="print the messages")
    mode.add_argument("-p", "--pub", metavar="TEXT", help="publish one message (with -m)")
    parser.add_argument("-t", "--topic", metavar="TOPIC")
    parser.add_argument("-m", "--msgtype", metavar="TYPE", help="e.g. gz.msgs.Twist")
    parser.add_argument("-n", "--num", type=int, default=None, help="-e: stop after N")
    parser.add_argument("-d", "--duration", type=float, default=None, help="-e: stop after S s")
    parser.add_argument("--json-output", action="store_true", help="-e: print JSON")
    args = parser.parse_args(argv)
    if not (args.list or args.info or args.echo or args.pub is not None):
        parser.error("give one of -l, -i, -e or -p")
    if not args.list and not args.topic:
        parser.error("-t TOPIC is required with -i, -e and -p")
    if args.list:
        return _topic_list()
    if args.info:
        return _topic_info(args.topic)
    if args.echo:
        return _echo(args.topic, args.num, args.duration, args.json_output)
    if not args.msgtype:
        parser.error("-p needs the message type: -m gz.msgs.NAME")
    return _publish(args.topic, args.msgtype, args.pub)


def _sim_topics(session: Any) -> dict[str, graph.TopicInfo]:
    return {name: info for name, info in graph.topics(session).items()
            if any(t.startswith(f"{SIM}/") for t in info.types)}


def gz_name(type_name: str) -> str:
    short = type_name.rsplit("/", 1)[-1]
    return "gz.msgs.Pose_V" if short == "PoseV" else f"gz.msgs.{short}"


def _topic_list() -> int:
    session = open_session("client")
    try:
        for name in sorted(_sim_topics(session)):
            print(name)
    finally:
        session.close()
    return 0


def _topic_info(name: str) -> int:
    session = open_session("client")
    try:
        found = [e for e in graph.entities(session) if e.topic == name
                 and e.kind in (keys.PUBLISHER, keys.SUBSCRIPTION)]
    finally:
        session.close()
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
    return 0


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
    node = Node("_launcher_gz_topic", argv=[], parameter_services=False, session=session)
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


def parse_text(text: str, what: str) -> dict[str, Any]:
    try:
        return prototext.parse(text, what)
    except prototext.TextFormatError as exc:
        raise GzUsage(exc.message) from None


def message_type(gz_type: str) -> tuple[str, str]:
    """(the sim's type, Gazebo's short name) for `gz.msgs.NAME`."""
    short = _short(gz_type)
    if not short:
        raise GzUsage(f"unknown message type '{gz_type}': expected gz.msgs.NAME"
                      f"{did_you_mean(gz_type, [f'gz.msgs.{m}' for m in SIM_MESSAGES])}")
    try:
        return sim_type(gz_type), short
    except LaunchError as exc:
        raise GzUsage(exc.message) from None


def parse_message(gz_type: str, text: str, what: str) -> Any:
    """A sim message from Gazebo's text format for `gz_type`; fields are checked."""
    type_name, short = message_type(gz_type)
    data = gz_msgs.to_sim(short, parse_text(text, what))
    try:
        return build(type_name, data)
    except MessageError as exc:
        message = exc.message.replace(type_name, gz_type)
        raise GzUsage(f"{what}: '{text}' does not fit {gz_type}: {message}") from None


def _publish(name: str, gz_type: str, text: str) -> int:
    message = parse_message(gz_type, text, "-p")
    type_name = message_type(gz_type)[0]
    session = open_session("client")
    info = _sim_topics(session).get(name) or graph.topics(session).get(name)
    if info is not None and info.types and type_name not in info.types:
        session.close()
        raise LaunchError(f"topic [{name}] carries {', '.join(map(gz_name, info.types))}, "
                          f"not {gz_type}")
    node = Node("_launcher_gz_topic", argv=[], parameter_services=False, session=session)
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


# --- gz service ----------------------------------------------------------------------------
def service(argv: list[str]) -> int:
    parser = _Parser(prog="gz service", description="Gazebo's services of launcher's sim.",
                     allow_abbrev=False)
    parser.add_argument("-l", "--list", action="store_true", help="list the sim's services")
    parser.add_argument("-i", "--info", action="store_true", help="the service's types")
    parser.add_argument("-s", "--service", metavar="SERVICE")
    parser.add_argument("--reqtype", metavar="TYPE", help="e.g. gz.msgs.WorldControl")
    parser.add_argument("--reptype", metavar="TYPE", help="e.g. gz.msgs.Boolean")
    parser.add_argument("--timeout", type=float, default=1000.0, metavar="MS")
    parser.add_argument("--req", metavar="TEXT", help="the request, in text format")
    args = parser.parse_args(argv)
    if args.list:
        return _service_list()
    if not args.service:
        parser.error("-s SERVICE is required with -i and --req")
    if args.info:
        return _service_info(args.service)
    if not (args.reqtype and args.reptype and args.req is not None):
        parser.error("a call needs --reqtype, --reptype and --req")
    return _call(args.service, args.reqtype, args.reptype, args.req, args.timeout / 1000.0)


def _services(session: Any) -> list[keys.Entity]:
    return [e for e in graph.entities(session)
            if e.kind == keys.SERVICE and e.type_name.startswith(f"{SIM}/")]


def _service_list() -> int:
    session = open_session("client")
    try:
        for name in sorted({e.topic for e in _services(session)}):
            print(name)
    finally:
        session.close()
    return 0


def _service_info(name: str) -> int:
    session = open_session("client")
    try:
        found = [e for e in _services(session) if e.topic == name]
    finally:
        session.close()
    if not found:
        raise LaunchError(f"no service [{name}] on the sim")
    print("Service providers [Node, Service Type]:")
    for entity in found:
        print(f"  {entity.node_fqn}, {entity.type_name}")
    return 0


def _call(name: str, reqtype: str, reptype: str, text: str, timeout: float) -> int:
    try:
        service_type = sim_type(f"{reqtype}|{reptype}")
    except LaunchError as exc:
        raise GzUsage(exc.message) from None
    request_short = _short(reqtype)
    data = gz_msgs.to_sim(request_short, parse_text(text, "--req"))
    node = Node("_launcher_gz_service", argv=[], parameter_services=False)
    try:
        client = node.create_client(service_type, name)
        try:
            request = build(client.request_type, data)
        except MessageError as exc:
            raise GzUsage(f"--req: '{text}' does not fit {reqtype}: "
                          f"{exc.message.replace(client.request_type, reqtype)}") from None
        if not client.wait_for_service(max(timeout, 0.5)):
            raise LaunchError(f"service [{name}] ({reqtype} -> {reptype}) is not offered "
                              "(`gz service -l` lists the sim's services)")
        response = client.call(request, max(timeout, 0.1))
    finally:
        node.destroy_node()
    reply = to_data(response)
    print(prototext.format(gz_msgs.reply_to_gz(_short(reptype), reply)) or "data: false\n")
    if not reply.get("success", True):
        print(f"the sim refused: {reply.get('message', '')}", file=sys.stderr)
        return 1
    return 0


# --- gz model ------------------------------------------------------------------------------
def model(argv: list[str]) -> int:
    parser = _Parser(prog="gz model", description="Models of launcher's running world.",
                     allow_abbrev=False)
    parser.add_argument("--list", action="store_true", help="list the models")
    parser.add_argument("-m", "--model", metavar="NAME")
    parser.add_argument("-p", "--pose", action="store_true", help="the model's pose")
    parser.add_argument("--timeout", type=float, default=5.0, help="seconds to wait for a sim")
    args = parser.parse_args(argv)
    if not args.list and not args.model:
        parser.error("give --list or -m NAME")
    node = Node("_launcher_gz_model", argv=[], parameter_services=False)
    try:
        deadline = time.monotonic() + args.timeout
        try:
            world = find_world(node, deadline, args.timeout, "state", STATE_TYPE, "--world")
        except (UsageError, TimeoutError) as exc:
            raise LaunchError(f"{exc}; is the sim running?") from None
        client = node.create_client(STATE_TYPE, f"/world/{world}/state")
        client.wait_for_service(max(0.5, deadline - time.monotonic()))
        state = client.call(node.message(f"{STATE_TYPE}_Request"), args.timeout)
    finally:
        node.destroy_node()
    print(f"Requesting state for world [{world}]...\n")
    names = list(state.name)
    if args.list:
        print("Available models:")
        for name in names:
            print(f"    - {name}")
        return 0
    if args.model not in names:
        raise LaunchError(f"no model named '{args.model}' in world '{world}'"
                          f"{did_you_mean(args.model, names)}")
    pose = state.pose[names.index(args.model)]
    p, q = pose.position, pose.orientation
    roll, pitch, yaw = _rpy(q.w, q.x, q.y, q.z)
    print(f"Model: [{args.model}]")
    print("  - Pose [ XYZ (m) ] [ RPY (rad) ]:")
    print(f"      [{p.x:.6f} {p.y:.6f} {p.z:.6f}]")
    print(f"      [{roll:.6f} {pitch:.6f} {yaw:.6f}]")
    return 0


def _rpy(w: float, x: float, y: float, z: float) -> tuple[float, float, float]:
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return roll, pitch, yaw
