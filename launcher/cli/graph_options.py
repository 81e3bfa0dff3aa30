"""The options listing verbs share about what of the graph they show: the ROS graph or, with
`--sim`, the simulator's own topics and services (Gazebo's gz-transport side); hidden names;
types."""

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


def add_hidden_option(parser: argparse.ArgumentParser, what: str) -> None:
    """`--include-hidden-WHAT`, as ros2cli's listings have it."""
    parser.add_argument(f"--include-hidden-{what}", action="store_true",
                        help=f"also the hidden ones (a name part that begins with '_', as "
                             f"actions' /_action/ {what}), which ros2 leaves out")


def add_types_option(parser: argparse.ArgumentParser, of: str) -> None:
    parser.add_argument("-t", "--show-types", action="store_true", help=f"each {of} type too")
