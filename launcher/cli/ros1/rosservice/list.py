"""`rosservice list`: list active services."""

from __future__ import annotations

import argparse

from launcher.bus.names import below
from launcher.cli.ros1.rosservice.lookup import service_servers


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-n", "--nodes", action="store_true",
                        help="print the node that provides each service")
    parser.add_argument("namespace", nargs="?", help="only services below this namespace")


def run(args: argparse.Namespace) -> int:
    prefix = below(args.namespace)
    found = sorted({(e.topic, e.node_fqn) for e in service_servers() if e.topic.startswith(prefix)
                    and "/_action/" not in e.topic})
    for name, node in found if args.nodes else sorted({(n, "") for n, _ in found}):
        print(f"{name} {node}" if args.nodes else name)
    return 0
