"""A node's parameter services, called from the command line."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.bus import parameters as params
from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.cli import completion, positive_number


def call_parameters(args: argparse.Namespace, service: str, suffix: str, request: dict) -> object:
    node = Node("_launcher_param", argv=[], parameter_services=False)
    try:
        client = node.create_client(service, f"{args.node.rstrip('/')}/{suffix}")
        request_type, _ = client.request_type, client.response_type
        return client.call(build(request_type, request), args.timeout)
    finally:
        node.destroy_node()


def parameter_message(name: str, value: Any) -> dict:
    message = params.to_message(value)
    return {"name": name, "value": {f: getattr(message, f) for f in message.__dataclass_fields__
                                    if f != "__msgtype__"}}


def add_node_argument(parser: argparse.ArgumentParser) -> None:
    """NODE, which every verb of `param` takes first."""
    parser.add_argument("node", help="the node's full name").completer = \
        completion.nodes  # type: ignore[attr-defined]


def add_names_arguments(parser: argparse.ArgumentParser) -> None:
    """NODE NAME… [--timeout], as `param delete` and `param describe` take them."""
    add_node_argument(parser)
    parser.add_argument("names", nargs="+", metavar="name", help="the parameters")
    add_timeout_option(parser)


def add_timeout_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the node's answer (default 5 s)")
