"""`launcher gz sim|topic|service|model …`: Gazebo's command line over launcher's sim.

`launcher gz sim` is `launcher sim` (the workspace's hooks applied); the other verbs are
clients of the running sim (launcher/nodes/gz/). Launched processes find the same program
as `gz` on their PATH when no real Gazebo is installed (see compat/bin).
"""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Its words, described (a run takes them as typed: `main`)."""
    parser.description = ("Gazebo's commands over launcher's sim (see `launcher gz -h`).")
    parser.add_argument("arguments", nargs=argparse.REMAINDER)


def main(argv: list[str], prog: str = "") -> int:
    """The words after `gz` (a tool: cli/commands.py)."""
    if argv[:1] == ["sim"]:
        from launcher.cli.sim_command import run_sim

        return run_sim(argv[1:], gz=True)
    from launcher.nodes.gz import main as gz

    return gz(argv)
