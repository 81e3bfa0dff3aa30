"""`launcher interface proto`: a message's fields with their defaults, as YAML."""

from __future__ import annotations

import argparse

from launcher.cli.interface.types import ensure_known


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("type", help="a message type, e.g. geometry_msgs/msg/Twist")


def run(args: argparse.Namespace) -> int:
    import yaml

    from launcher.bus.messages import build, to_data
    from launcher.bus.types import normalize

    name = normalize(args.type)
    ensure_known(name)
    data = to_data(build(name, {}))
    print(f'"{yaml.safe_dump(data, default_flow_style=False, sort_keys=False)}"')
    return 0
