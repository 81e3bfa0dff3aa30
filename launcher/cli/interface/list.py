"""`launcher interface list`: every message and service type."""

from __future__ import annotations

import argparse

from launcher.cli.interface.types import all_types


def add_arguments(parser: argparse.ArgumentParser) -> None:
    only = parser.add_mutually_exclusive_group()
    only.add_argument("-m", "--only-msgs", action="store_true", help="messages only")
    only.add_argument("-s", "--only-srvs", action="store_true", help="services only")


def run(args: argparse.Namespace) -> int:
    types = all_types()
    for kind, title in (("msg", "Messages"), ("srv", "Services")):
        if (kind == "msg" and args.only_srvs) or (kind == "srv" and args.only_msgs):
            continue
        print(f"{title}:")
        for name in types[kind]:
            print(f"    {name}")
    return 0
