"""`launcher gz sim|topic|service|model …`: Gazebo's command line over launcher's sim.

`launcher gz sim` is `launcher sim` (the workspace's hooks applied); the other verbs are
clients of the running sim (launcher/nodes/gz/). Launched processes find the same program
as `gz` on their PATH when no real Gazebo is installed (see compat/bin).
"""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = ("Gazebo's commands over launcher's sim (see `launcher gz -h`).")
    parser.add_argument("arguments", nargs=argparse.REMAINDER)


def run(args: argparse.Namespace) -> int:
    return run_gz(args.arguments)


def run_gz(argv: list[str]) -> int:
    if argv[:1] == ["sim"]:
        from launcher.cli.sim_command import run_sim

        return run_sim(argv[1:], gz=True)
    from launcher.nodes.gz import main

    return main(argv)


def main(argv: list[str], prog: str = "") -> int:
    """As a tool of its own (cli/main.py's TOOLS): the words after its name."""
    return run_gz(argv)
