"""`launcher service call`: call a service once."""

from __future__ import annotations

import argparse
import time

import yaml

from launcher.bus.messages import to_data
from launcher.bus.node import Node
from launcher.bus.types import registry
from launcher.cli import completion, positive_number
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.message_text import message_from


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the service").completer = completion.services  # type: ignore[attr-defined]
    parser.add_argument("type", help="its type, e.g. std_srvs/srv/Trigger")
    parser.add_argument("values", nargs="?", default="{}", help="the request as YAML")
    parser.add_argument("--timeout", type=float, default=5.0,
                        help="seconds to wait for the answer")
    parser.add_argument("-r", "--rate", type=positive_number, default=None, metavar="HZ",
                        help="call again and again at this rate (calls per second) until Ctrl-C")
    add_sim_option(parser, "services")


def run(args: argparse.Namespace) -> int:
    request_type, _ = registry().service(args.type)
    request = message_from(request_type, args.values, "request")
    node = Node("_launcher_service_call", argv=[], parameter_services=False,
                space=space_of(args))
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
