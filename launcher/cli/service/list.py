"""`launcher service list`: the services on the bus."""

from __future__ import annotations

import argparse

from launcher.bus import keys
from launcher.bus.names import hidden
from launcher.cli.service.lookup import graph_services
from launcher.cli.space import add_sim_option


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--include-hidden-services", action="store_true",
                        help="also the hidden ones (a name part that begins with '_', as "
                             "actions' /_action/ services), which ros2 leaves out")
    parser.add_argument("-t", "--show-types", action="store_true",
                        help="each service's type too")
    add_sim_option(parser, "services")


def run(args: argparse.Namespace) -> int:
    found = {(e.topic, e.type_name) for e in graph_services(args) if e.kind == keys.SERVICE
             and (args.include_hidden_services or not hidden(e.topic))}
    for name, type_name in sorted(found):
        print(f"{name} [{type_name}]" if args.show_types else name)
    return 0
