"""`launcher service list`: the services on the bus."""

from __future__ import annotations

import argparse

from launcher.bus import keys
from launcher.bus.names import hidden
from launcher.cli.graph_options import add_hidden_option, add_sim_option, add_types_option
from launcher.cli.service.lookup import graph_services


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_hidden_option(parser, "services")
    add_types_option(parser, "service's")
    add_sim_option(parser, "services")


def run(args: argparse.Namespace) -> int:
    found = {(e.topic, e.type_name) for e in graph_services(args) if e.kind == keys.SERVICE
             and (args.include_hidden_services or not hidden(e.topic))}
    for name, type_name in sorted(found):
        print(f"{name} [{type_name}]" if args.show_types else name)
    return 0
