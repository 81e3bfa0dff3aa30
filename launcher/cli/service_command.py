"""`launcher service list | call | type | find | info`, and `launcher node list | info`, as
`ros2` has them."""

from __future__ import annotations

import argparse
import time

import yaml

from launcher.bus import graph, keys
from launcher.bus.messages import build, to_data
from launcher.bus.names import hidden
from launcher.bus.node import Node
from launcher.bus.session import open_session
from launcher.bus.types import registry
from launcher.cli import completion, positive_number
from launcher.errors import LaunchError, UsageError, did_you_mean


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("service", help="services: list, call, type, find, info")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="the services on the bus")
    listing.add_argument("--include-hidden-services", action="store_true",
                         help="also the hidden ones (a name part that begins with '_', as "
                              "actions' /_action/ services), which ros2 leaves out")
    listing.add_argument("-t", "--show-types", action="store_true",
                         help="each service's type too")
    listing.set_defaults(run=run_list)
    call = verbs.add_parser("call", help="call a service once")
    call.add_argument("name", help="the service").completer = completion.services  # type: ignore[attr-defined]
    call.add_argument("type", help="its type, e.g. std_srvs/srv/Trigger")
    call.add_argument("values", nargs="?", default="{}", help="the request as YAML")
    call.add_argument("--timeout", type=float, default=5.0,
                      help="seconds to wait for the answer")
    call.add_argument("-r", "--rate", type=positive_number, default=None, metavar="HZ",
                      help="call again and again at this rate (calls per second) until Ctrl-C")
    call.set_defaults(run=run_call)
    kind = verbs.add_parser("type", help="the type of a service")
    kind.add_argument("name", help="the service").completer = completion.services  # type: ignore[attr-defined]
    kind.set_defaults(run=run_type)
    find = verbs.add_parser("find", help="the services of a type")
    find.add_argument("type", help="a service type (std_srvs/srv/Trigger)")
    find.set_defaults(run=run_find)
    info = verbs.add_parser("info", help="a service's type, and how many serve and call it")
    info.add_argument("name", help="the service").completer = completion.services  # type: ignore[attr-defined]
    info.set_defaults(run=run_info)
    verb_echo = echo = verbs.add_parser(
        "echo", help="a service's events (its servers and clients must have introspection on)")
    echo.add_argument("name", help="the service").completer = completion.services  # type: ignore[attr-defined]
    echo.add_argument("type", nargs="?", help="its type (found on the graph when left out)")
    echo.add_argument("--once", action="store_true", help="one event, then exit")
    echo.set_defaults(run=run_echo)
    for verb in (listing, call, kind, find, info, verb_echo):
        verb.add_argument("--sim", action="store_true",
                          help="the simulator's own services (Gazebo's gz-transport side), not "
                               "the ROS graph's")


def _space(args: argparse.Namespace) -> keys.Space:
    return keys.SIM if args.sim else keys.ROS


def run_list(args: argparse.Namespace) -> int:
    found = {(e.topic, e.type_name) for e in _services(args) if e.kind == keys.SERVICE
             and (args.include_hidden_services or not hidden(e.topic))}
    for name, type_name in sorted(found):
        print(f"{name} [{type_name}]" if args.show_types else name)
    return 0


def _services(args: argparse.Namespace) -> list[keys.Entity]:
    session = open_session("client")
    found = [e for e in graph.entities(session, space=_space(args))
             if e.kind in (keys.SERVICE, keys.CLIENT)]
    session.close()
    return found


def _named(args: argparse.Namespace) -> list[keys.Entity]:
    found = _services(args)
    mine = [e for e in found if e.topic == args.name]
    if not any(e.kind == keys.SERVICE for e in mine):
        known = sorted({e.topic for e in found if e.kind == keys.SERVICE})
        raise LaunchError(f"unknown service '{args.name}'{did_you_mean(args.name, known)}")
    return mine


def run_type(args: argparse.Namespace) -> int:
    for name in sorted({e.type_name for e in _named(args) if e.kind == keys.SERVICE}):
        print(name)
    return 0


def run_find(args: argparse.Namespace) -> int:
    for name in sorted({e.topic for e in _services(args)
                        if e.kind == keys.SERVICE and e.type_name == args.type}):
        print(name)
    return 0


def run_info(args: argparse.Namespace) -> int:
    mine = _named(args)
    types = sorted({e.type_name for e in mine if e.kind == keys.SERVICE})
    print(f"Type: {', '.join(types)}")
    print(f"Clients count: {sum(e.kind == keys.CLIENT for e in mine)}")
    print(f"Services count: {sum(e.kind == keys.SERVICE for e in mine)}")
    return 0


def run_call(args: argparse.Namespace) -> int:
    try:
        values = yaml.safe_load(args.values)
    except yaml.YAMLError as exc:
        raise UsageError(f"the request is not valid YAML: {exc}") from None
    request_type, _ = registry().service(args.type)
    request = build(request_type, values)
    node = Node("_launcher_service_call", argv=[], parameter_services=False,
                space=_space(args))
    try:
        client = node.create_client(args.type, args.name)
        while True:
            start = time.monotonic()
            print(f"requester: making request: {to_data(request)}\n")
            response = client.call(request, args.timeout)
            print("response:\n" + yaml.safe_dump(to_data(response), sort_keys=False),
                  end="", flush=True)
            if args.rate is None or node.interrupted:
                break
            node.spin(max(0.0, 1.0 / args.rate - (time.monotonic() - start)))
            if node.interrupted:
                break
            print()
    finally:
        node.destroy_node()
    return 0


def add_node_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("node", help="nodes: list, info")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="the nodes on the bus")
    listing.add_argument("-a", "--all", action="store_true",
                         help="hidden nodes too (names that begin with '_')")
    listing.set_defaults(run=run_nodes)
    info = verbs.add_parser("info", help="a node's publishers, subscriptions, services")
    info.add_argument("name", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    info.set_defaults(run=run_node_info)


def run_nodes(args: argparse.Namespace) -> int:
    session = open_session("client")
    for name in sorted({e.node_fqn for e in graph.nodes(session)
                        if getattr(args, "all", False) or not e.node.startswith("_")}):
        print(name)
    session.close()
    return 0


def run_node_info(args: argparse.Namespace) -> int:
    session = open_session("client")
    mine = [e for e in graph.entities(session) if e.node_fqn == args.name]
    session.close()
    if not mine:
        raise LaunchError(f"no node '{args.name}' on the bus")
    print(args.name)
    for kind, title in ((keys.SUBSCRIPTION, "Subscribers"), (keys.PUBLISHER, "Publishers"),
                        (keys.SERVICE, "Service Servers"), (keys.CLIENT, "Service Clients")):
        print(f"  {title}:")
        for entity in sorted((e for e in mine if e.kind == kind), key=lambda e: e.topic):
            print(f"    {entity.topic}: {entity.type_name}")
    return 0


def run_echo(args: argparse.Namespace) -> int:
    """`ros2 service echo`: the events on `<name>/_service_event`, as YAML, `---` between."""
    type_name = args.type
    if type_name is None:
        types = sorted({e.type_name for e in _named(args) if e.kind == keys.SERVICE})
        type_name = types[0]
    event = registry().service_event(type_name)
    node = Node("_launcher_service_echo", argv=[], parameter_services=False,
                space=_space(args))
    done = [False]

    def show(message: object) -> None:
        if done[0]:
            return
        print(yaml.safe_dump(to_data(message), sort_keys=False) + "---", flush=True)
        if args.once:
            done[0] = True
            node.shutdown()
    try:
        node.create_subscription(event, f"{args.name}/_service_event", show)
        node.spin()
    finally:
        node.destroy_node()
    return 0
