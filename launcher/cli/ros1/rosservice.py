"""`rosservice list | call | type | info`, as ROS 1's rosservice: the type found on the graph,
the request from YAML or the fields in order (`rosservice call /gazebo/reset_world` needs
none), and the response printed as YAML alone."""

from __future__ import annotations

import argparse

from launcher.arguments import Parser
from launcher.bus import graph, keys
from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import expand
from launcher.bus.session import open_session
from launcher.errors import LaunchError, did_you_mean


def parser(prog: str = "rosservice") -> Parser:
    p = Parser(prog=prog, description="rosservice is a command-line tool for printing "
                                      "information about ROS Services.")
    verbs = p.add_subparsers(dest="verb", metavar="COMMAND", required=True)
    listing = verbs.add_parser("list", help="list active services")
    listing.add_argument("-n", "--nodes", action="store_true",
                         help="print the node that provides each service")
    listing.add_argument("namespace", nargs="?", help="only services below this namespace")
    listing.set_defaults(run=run_list)
    call = verbs.add_parser("call", help="call the service with the provided args")
    call.add_argument("service", help="the service")
    call.add_argument("values", nargs="*", help="the request: YAML, or its fields in order")
    call.add_argument("--wait", action="store_true", help="wait for the service to appear")
    call.set_defaults(run=run_call)
    kind = verbs.add_parser("type", help="print service type")
    kind.add_argument("service", help="the service")
    kind.set_defaults(run=run_type)
    info = verbs.add_parser("info", help="print information about service")
    info.add_argument("service", help="the service")
    info.set_defaults(run=run_info)
    return p


def main(argv: list[str], prog: str = "rosservice") -> int:
    args = parser(prog).parse_args_strictly(argv)
    return int(args.run(args) or 0)


def _servers() -> list[keys.Entity]:
    session = open_session("client")
    try:
        return [e for e in graph.entities(session) if e.kind == keys.SERVICE]
    finally:
        session.close()


def _providers(name: str, servers: list[keys.Entity]) -> list[keys.Entity]:
    mine = [e for e in servers if e.topic == name]
    if not mine:
        known = sorted({e.topic for e in servers})
        raise LaunchError(f"Service [{name}] is not available{did_you_mean(name, known)}")
    return mine


def run_list(args: argparse.Namespace) -> int:
    below = expand(args.namespace).rstrip("/") + "/" if args.namespace else "/"
    found = sorted({(e.topic, e.node_fqn) for e in _servers() if e.topic.startswith(below)
                    and "/_action/" not in e.topic})
    for name, node in found if args.nodes else sorted({(n, "") for n, _ in found}):
        print(f"{name} {node}" if args.nodes else name)
    return 0


def run_type(args: argparse.Namespace) -> int:
    for name in sorted({e.type_name for e in _providers(expand(args.service), _servers())}):
        print(ros1_spelling(name))
    return 0


def run_info(args: argparse.Namespace) -> int:
    from launcher.bus.messages import build, to_data
    from launcher.bus.types import registry

    mine = _providers(expand(args.service), _servers())
    type_name = mine[0].type_name
    request, _ = registry().service(type_name)
    print(f"Node: {mine[0].node_fqn}")
    print(f"Type: {ros1_spelling(type_name)}")
    print(f"Args: {' '.join(to_data(build(request, {})))}")
    return 0


def run_call(args: argparse.Namespace) -> int:
    import time

    import yaml

    from launcher.bus.messages import build, to_data
    from launcher.bus.node import Node
    from launcher.bus.types import registry
    from launcher.cli.ros1.rostopic import message_values

    name = expand(args.service)
    while True:
        try:
            type_name = _providers(name, _servers())[0].type_name
            break
        except LaunchError:
            if not args.wait:
                raise
            time.sleep(0.5)
    request_type, _ = registry().service(type_name)
    request = build(request_type, message_values(request_type, args.values))
    node = Node("_rosservice_call", argv=[], parameter_services=False)
    try:
        response = node.create_client(type_name, name).call(request, 10.0)
    finally:
        node.destroy_node()
    data = {k: v for k, v in to_data(response).items()
            if k != "structure_needs_at_least_one_member"}  # ROS 2's filler of an empty one
    if data:
        print(yaml.safe_dump(data, sort_keys=False, default_flow_style=False), end="")
    return 0
