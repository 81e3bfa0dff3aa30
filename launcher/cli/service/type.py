"""`launcher service type`: the type of a service."""

from __future__ import annotations

import argparse

from launcher.bus import keys
from launcher.cli import completion
from launcher.cli.graph_options import add_sim_option
from launcher.cli.service.lookup import named_service


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", help="the service").completer = completion.services  # type: ignore[attr-defined]
    add_sim_option(parser, "services")


def run(args: argparse.Namespace) -> int:
    for name in sorted({e.type_name for e in named_service(args) if e.kind == keys.SERVICE}):
        print(name)
    return 0
