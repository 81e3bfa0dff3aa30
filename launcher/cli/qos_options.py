"""The `--qos-*` options that `ros2 topic echo` (and `pub`, `bag record`) take, as a QoS."""

from __future__ import annotations

import argparse

from launcher.bus.qos import QoS
from launcher.cli import positive_count

# rclpy's named profiles, as the bus keeps QoS (depth, reliable, transient local)
PROFILES = {
    "system_default": QoS(depth=10),
    "default": QoS(depth=10),
    "sensor_data": QoS(depth=5, reliable=False),
    "services_default": QoS(depth=10),
    "parameters": QoS(depth=1000),
    "parameter_events": QoS(depth=1000),
    "action_status_default": QoS(depth=1, transient_local=True),
    # matches any publisher: reliable and transient local take what each one offers
    "best_available": QoS(depth=10, transient_local=True),
}
KEEP_ALL_DEPTH = 1000  # keep_all as the bus keeps it: a queue far deeper than a reader lags


def add(parser: argparse.ArgumentParser, default: str) -> None:
    parser.add_argument("--qos-profile", choices=sorted(PROFILES), default=default,
                        help=f"the QoS profile to start from (default: {default})")
    parser.add_argument("--qos-depth", type=positive_count, metavar="N",
                        help="queue depth (messages), overriding the profile's")
    parser.add_argument("--qos-history", choices=("system_default", "keep_last", "keep_all"),
                        help="keep_last (depth messages) or keep_all")
    parser.add_argument("--qos-reliability",
                        choices=("system_default", "reliable", "best_effort"),
                        help="reliable or best_effort, overriding the profile's")
    parser.add_argument("--qos-durability",
                        choices=("system_default", "volatile", "transient_local"),
                        help="volatile or transient_local (latched), overriding the profile's")


def chosen(args: argparse.Namespace) -> QoS:
    """The profile with the overrides the command line gives."""
    base = PROFILES[args.qos_profile]
    depth, reliable, latched = base.depth, base.reliable, base.transient_local
    if args.qos_history == "keep_all":
        depth = KEEP_ALL_DEPTH
    if args.qos_depth is not None:
        depth = args.qos_depth
    if args.qos_reliability in ("reliable", "best_effort"):
        reliable = args.qos_reliability == "reliable"
    if args.qos_durability in ("volatile", "transient_local"):
        latched = args.qos_durability == "transient_local"
    return QoS(depth=depth, reliable=reliable, transient_local=latched)
