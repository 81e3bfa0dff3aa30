"""`rosservice info`: print information about service."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import expand
from launcher.cli.ros1.rosservice.lookup import providers_of, service_servers


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("service", help="the service")


def run(args: argparse.Namespace) -> int:
    from launcher.bus.messages import build, to_data
    from launcher.bus.types import registry

    mine = providers_of(expand(args.service), service_servers())
    type_name = mine[0].type_name
    request, _ = registry().service(type_name)
    print(f"Node: {mine[0].node_fqn}")
    print(f"Type: {ros1_spelling(type_name)}")
    print(f"Args: {' '.join(to_data(build(request, {})))}")
    return 0
