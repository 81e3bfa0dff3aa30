"""The `--qos-*` options that `ros2 topic echo` (and `pub`, `bag record`) take, as a QoS."""

from __future__ import annotations

import argparse

from launcher.bus import qos
from launcher.cli import positive_count

COMMAND_LINE_PROFILES = sorted(set(qos.PROFILES) - {"rosout_default"})  # ros2cli's choices


def add(parser: argparse.ArgumentParser, default: str) -> None:
    parser.add_argument("--qos-profile", choices=COMMAND_LINE_PROFILES, default=default,
                        help=f"the QoS profile to start from (default: {default})")
    parser.add_argument("--qos-depth", type=positive_count, metavar="N",
                        help="queue depth (messages), overriding the profile's")
    parser.add_argument("--qos-history", choices=qos.HISTORY,
                        help="keep_last (depth messages) or keep_all")
    parser.add_argument("--qos-reliability", choices=qos.RELIABILITY,
                        help="reliable or best_effort, overriding the profile's")
    parser.add_argument("--qos-durability", choices=qos.DURABILITY,
                        help="volatile or transient_local (latched), overriding the profile's")


def chosen(args: argparse.Namespace) -> qos.QoS:
    """The profile with the overrides the command line gives."""
    return qos.PROFILES[args.qos_profile].with_policies(
        args.qos_history, args.qos_depth, args.qos_reliability, args.qos_durability)
