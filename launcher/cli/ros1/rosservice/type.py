"""`rosservice type`: print service type."""

from __future__ import annotations

import argparse

from launcher.bus.interfaces import ros1_spelling
from launcher.bus.names import expand
from launcher.cli.ros1.rosservice.lookup import providers_of, service_servers


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("service", help="the service")


def run(args: argparse.Namespace) -> int:
    providers = providers_of(expand(args.service), service_servers())
    for name in sorted({e.type_name for e in providers}):
        print(ros1_spelling(name))
    return 0
