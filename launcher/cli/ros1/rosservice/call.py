"""`rosservice call`: call the service with the provided args."""

from __future__ import annotations

import argparse

from launcher.bus.names import expand
from launcher.cli.ros1.rosservice.lookup import providers_of, service_servers
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("service", help="the service")
    parser.add_argument("values", nargs="*", help="the request: YAML, or its fields in order")
    parser.add_argument("--wait", action="store_true", help="wait for the service to appear")


def run(args: argparse.Namespace) -> int:
    import time

    import yaml

    from launcher.bus.messages import build, to_data
    from launcher.bus.node import Node
    from launcher.bus.types import registry
    from launcher.cli.ros1.values import message_values

    name = expand(args.service)
    while True:
        try:
            type_name = providers_of(name, service_servers())[0].type_name
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
