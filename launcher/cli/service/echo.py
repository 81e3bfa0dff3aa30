"""`launcher service echo`: a service's events (its servers and clients must have
introspection on)."""

from __future__ import annotations

import argparse

import yaml

from launcher.bus import keys
from launcher.bus.messages import to_data
from launcher.bus.node import Node
from launcher.bus.types import registry
from launcher.cli import completion
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.service.lookup import named_service


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the service").completer = completion.services  # type: ignore[attr-defined]
    parser.add_argument("type", nargs="?", help="its type (found on the graph when left out)")
    parser.add_argument("--once", action="store_true", help="one event, then exit")
    add_sim_option(parser, "services")


def run(args: argparse.Namespace) -> int:
    """`ros2 service echo`: the events on `<name>/_service_event`, as YAML, `---` between."""
    type_name = args.type
    if type_name is None:
        types = sorted({e.type_name for e in named_service(args) if e.kind == keys.SERVICE})
        type_name = types[0]
    event = registry().service_event(type_name)
    node = Node("_launcher_service_echo", argv=[], parameter_services=False,
                space=space_of(args))
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
