"""Which graph a verb looks at: the ROS graph, or with `--sim` the simulator's own topics and
services (Gazebo's gz-transport side)."""

from __future__ import annotations

import argparse

from launcher.bus import keys


def add_sim_option(parser: argparse.ArgumentParser, what: str) -> None:
    """`--sim`: the simulator's own `what` (topics, services) instead of the ROS graph's."""
    parser.add_argument(
        "--sim", action="store_true",
        help=f"the simulator's own {what} (Gazebo's gz-transport side), not the ROS graph's")


def space_of(args: argparse.Namespace) -> keys.Space:
    return keys.SIM if args.sim else keys.ROS
