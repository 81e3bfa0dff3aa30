"""`gz model --list | -m NAME [-p]`: the running world's models, from its state service."""

from __future__ import annotations

import math
import time

from launcher.arguments import Parser
from launcher.bus import keys
from launcher.bus.node import Node
from launcher.errors import LaunchError, UsageError, did_you_mean
from launcher.nodes.conversions import SIM
from launcher.nodes.create import SimNotFound, find_world

STATE_TYPE = f"{SIM}/srv/State"


def build_parser() -> Parser:
    """`gz model`'s command line."""
    parser = Parser(prog="gz model", description="Models of launcher's running world.",
                     allow_abbrev=False)
    parser.add_argument("--list", action="store_true", help="list the models")
    parser.add_argument("-m", "--model", metavar="NAME", help="the model to show")
    parser.add_argument("-p", "--pose", action="store_true", help="the model's pose")
    parser.add_argument("--timeout", type=float, default=5.0, help="seconds to wait for a sim")
    return parser


def model(argv: list[str]) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not args.list and not args.model:
        parser.error("give --list or -m NAME")
    node = Node("_launcher_gz_model", argv=[], parameter_services=False, space=keys.SIM)
    try:
        deadline = time.monotonic() + args.timeout
        try:
            world = find_world(node, deadline, args.timeout, "state", STATE_TYPE, "--world")
        except (UsageError, SimNotFound) as exc:
            raise LaunchError(f"{exc}; is the sim running?") from None
        client = node.create_client(STATE_TYPE, f"/world/{world}/state")
        client.wait_for_service(max(0.5, deadline - time.monotonic()))
        state = client.call(node.message(f"{STATE_TYPE}_Request"), args.timeout)
    finally:
        node.destroy_node()
    print(f"Requesting state for world [{world}]...\n")
    names = list(state.name)
    if args.list:
        print("Available models:")
        for name in names:
            print(f"    - {name}")
        return 0
    if args.model not in names:
        raise LaunchError(f"no model named '{args.model}' in world '{world}'"
                          f"{did_you_mean(args.model, names)}")
    pose = state.pose[names.index(args.model)]
    p, q = pose.position, pose.orientation
    roll, pitch, yaw = _rpy(q.w, q.x, q.y, q.z)
    print(f"Model: [{args.model}]")
    print("  - Pose [ XYZ (m) ] [ RPY (rad) ]:")
    print(f"      [{p.x:.6f} {p.y:.6f} {p.z:.6f}]")
    print(f"      [{roll:.6f} {pitch:.6f} {yaw:.6f}]")
    return 0


def _rpy(w: float, x: float, y: float, z: float) -> tuple[float, float, float]:
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return roll, pitch, yaw
