"""`launcher service find`: the services of a type."""

from __future__ import annotations

import argparse

from launcher.bus import keys
from launcher.cli.graph_options import add_sim_option
from launcher.cli.service.lookup import graph_services


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("type", help="a service type (std_srvs/srv/Trigger)")
    add_sim_option(parser, "services")


def run(args: argparse.Namespace) -> int:
    for name in sorted({e.topic for e in graph_services(args)
                        if e.kind == keys.SERVICE and e.type_name == args.type}):
        print(name)
    return 0
