"""`launcher param list | get | set NODE …`, through the node's parameter services."""

from __future__ import annotations

import argparse

from launcher.bus import parameters as params
from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.bus.ros_args import typed


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("param", help="parameters of a running node: list, get, set")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="a node's parameter names")
    listing.add_argument("node")
    listing.set_defaults(run=run_list)
    get = verbs.add_parser("get", help="one parameter's value")
    get.add_argument("node")
    get.add_argument("name")
    get.set_defaults(run=run_get)
    put = verbs.add_parser("set", help="set one parameter (the value is read as YAML)")
    put.add_argument("node")
    put.add_argument("name")
    put.add_argument("value")
    put.set_defaults(run=run_set)
    for sub in (listing, get, put):
        sub.add_argument("--timeout", type=float, default=5.0)


def _call(args: argparse.Namespace, service: str, suffix: str, request: dict) -> object:
    node = Node("_launcher_param", argv=[], parameter_services=False)
    try:
        client = node.create_client(service, f"{args.node.rstrip('/')}/{suffix}")
        request_type, _ = client.request_type, client.response_type
        return client.call(build(request_type, request), args.timeout)
    finally:
        node.destroy_node()


def run_list(args: argparse.Namespace) -> int:
    response = _call(args, params.LIST, "list_parameters", {})
    print(f"{args.node}:")
    for name in response.result.names:
        print(f"  {name}")
    return 0


def run_get(args: argparse.Namespace) -> int:
    response = _call(args, params.GET, "get_parameters", {"names": [args.name]})
    print(params.describe(params.from_message(response.values[0])))
    return 0


def run_set(args: argparse.Namespace) -> int:
    value = params.to_message(typed(args.value))
    parameter = {"name": args.name, "value": {f: getattr(value, f)
                                              for f in value.__dataclass_fields__
                                              if f != "__msgtype__"}}
    response = _call(args, params.SET, "set_parameters", {"parameters": [parameter]})
    print("Set parameter successful" if response.results[0].successful else
          f"Setting parameter failed: {response.results[0].reason}")
    return 0
