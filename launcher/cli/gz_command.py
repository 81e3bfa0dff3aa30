"""`launcher gz sim|topic|service|model …`: Gazebo's command line over launcher's sim.

`launcher gz sim` is `launcher sim` (the workspace's hooks applied); the other verbs are
clients of the running sim (launcher/nodes/gz/). Launched processes find the same program
as `gz` on their PATH when no real Gazebo is installed (see compat/bin).
"""

from __future__ import annotations

import argparse


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "gz", help="Gazebo's commands (sim, topic, service, model) over launcher's sim",
        add_help=False, description="Gazebo's commands over launcher's sim (see `launcher gz -h`).")
    p.add_argument("arguments", nargs=argparse.REMAINDER)
    p.set_defaults(run=run)


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
