"""`launcher service list | call`, and `launcher node list | info`, as `ros2` has them."""

from __future__ import annotations

import argparse

import yaml

from launcher.bus import graph, keys
from launcher.bus.messages import build, to_data
from launcher.bus.node import Node
from launcher.bus.session import open_session
from launcher.bus.types import registry
from launcher.errors import LaunchError, UsageError


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("service", help="services: list, call")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="the services on the bus")
    listing.add_argument("-t", "--show-types", action="store_true")
    listing.set_defaults(run=run_list)
    call = verbs.add_parser("call", help="call a service once")
    call.add_argument("name")
    call.add_argument("type")
    call.add_argument("values", nargs="?", default="{}", help="the request as YAML")
    call.add_argument("--timeout", type=float, default=5.0)
    call.set_defaults(run=run_call)
    for verb in (listing, call):
        verb.add_argument("--sim", action="store_true",
                          help="the simulator's own services (Gazebo's gz-transport side), not "
                               "the ROS graph's")


def _space(args: argparse.Namespace) -> keys.Space:
    return keys.SIM if args.sim else keys.ROS


def run_list(args: argparse.Namespace) -> int:
    session = open_session("client")
    found = {(e.topic, e.type_name) for e in graph.entities(session, space=_space(args))
             if e.kind == keys.SERVICE}
    for name, type_name in sorted(found):
        print(f"{name} [{type_name}]" if args.show_types else name)
    session.close()
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
        print(f"requester: making request: {to_data(request)}\n")
        response = client.call(request, args.timeout)
    finally:
        node.destroy_node()
    print("response:\n" + yaml.safe_dump(to_data(response), sort_keys=False), end="")
    return 0


def add_node_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("node", help="nodes: list, info")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    verbs.add_parser("list", help="the nodes on the bus").set_defaults(run=run_nodes)
    info = verbs.add_parser("info", help="a node's publishers, subscriptions, services")
    info.add_argument("name")
    info.set_defaults(run=run_node_info)


def run_nodes(args: argparse.Namespace) -> int:
    session = open_session("client")
    for name in sorted({e.node_fqn for e in graph.nodes(session)
                        if not e.node.startswith("_launcher_")}):
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
