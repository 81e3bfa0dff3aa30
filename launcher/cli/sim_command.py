"""`launcher sim [FLAGS] [WORLD]`: run the world server here, with the workspace's hooks applied.

The same program as the `sim` executable of the mujoco_sim package (flags as `gz sim`'s; see
`launcher sim -h`); the hooks set MUJOCO_SIM_RESOURCE_PATH as `source setup.bash` would.
"""

from __future__ import annotations

import argparse
import os


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Its words, described (a run takes them as typed: `main`)."""
    parser.description = ("Run the MuJoCo world server (see `launcher sim -h`).")
    parser.add_argument("arguments", nargs=argparse.REMAINDER)


def main(argv: list[str], prog: str = "") -> int:
    """The words after `sim` (a tool: cli/commands.py)."""
    return run_sim(argv)


def run_sim(argv: list[str], gz: bool = False) -> int:
    """`gz` (as `launcher gz sim`): Gazebo's meaning, the web viewer unless -s."""
    if argv[:1] == ["snapshot"]:  # a client of the running sim, not a world named so
        from launcher.nodes.snapshot import main as snapshot

        return snapshot(argv[1:])
    from launcher.cli.workspace import hooked_environment, load_index

    os.environ.update(hooked_environment(load_index(), dict(os.environ)))  # errors: reported
    from launcher.nodes.sim import main

    return main(argv, gz=gz)
