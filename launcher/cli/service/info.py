"""`launcher service info`: a service's type, and how many serve and call it."""

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
    mine = named_service(args)
    types = sorted({e.type_name for e in mine if e.kind == keys.SERVICE})
    print(f"Type: {', '.join(types)}")
    print(f"Clients count: {sum(e.kind == keys.CLIENT for e in mine)}")
    print(f"Services count: {sum(e.kind == keys.SERVICE for e in mine)}")
    return 0
