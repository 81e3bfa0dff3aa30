"""A node's parameter services, called from the command line."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.bus import parameters as params
from launcher.bus.messages import build
from launcher.bus.node import Node


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
