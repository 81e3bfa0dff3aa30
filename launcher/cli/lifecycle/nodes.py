"""`launcher lifecycle nodes`: the lifecycle nodes on the graph."""

from __future__ import annotations

import argparse

from launcher.cli.lifecycle.client import lifecycle_nodes


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pass


def run(args: argparse.Namespace) -> int:
    for node in lifecycle_nodes():
        print(node)
    return 0
