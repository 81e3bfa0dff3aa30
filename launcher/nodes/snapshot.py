"""`launcher sim snapshot -o FILE.png`: a picture of the running world, rendered offscreen.

  launcher sim snapshot -o world.png [--world W] [--width 640] [--height 480]
                        [--camera NAME | --track ENTITY] [--timeout SECONDS]
The sim renders it (MUJOCO_GL=egl by default, osmesa also works) and answers with the PNG's
bytes; without --world, the one sim on the bus is used. Exit 0 when the file is written, 1
with the reason otherwise.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from launcher.arguments import Parser
from launcher.errors import LaunchError, UsageError, reported
from launcher.nodes.create import SimNotFound, find_world

SERVICE_TYPE = "mujoco_sim/srv/Snapshot"
MAX_SIDE = 4096  # as the sim allows


def build_parser() -> Parser:
    """`launcher sim snapshot`'s command line."""
    parser = Parser(
        prog="launcher sim snapshot",
        description="Render the running world offscreen to a PNG file.")
    parser.add_argument("-o", "--output", required=True, metavar="FILE.png",
                        help="the picture to write")
    parser.add_argument("--world", default="", help="the world's name (default: the one sim)")
    parser.add_argument("--width", type=int, default=640, help="pixels (default 640)")
    parser.add_argument("--height", type=int, default=480, help="pixels (default 480)")
    view = parser.add_mutually_exclusive_group()
    view.add_argument("--camera", default="", help="a camera of the world, by name")
    view.add_argument("--track", default="", metavar="ENTITY",
                      help="centre a free view on this entity (default: frame them all)")
    parser.add_argument("--timeout", type=float, default=10.0, metavar="SECONDS",
                        help="how long to wait for the sim (default 10)")
    return parser


def parse(argv: list[str]) -> argparse.Namespace:
    return build_parser().parse_args(argv)


def take(argv: list[str]) -> int:
    from launcher.bus import keys
    from launcher.bus.node import Node

    args = parse(argv)
    for flag, side in (("--width", args.width), ("--height", args.height)):
        if not 0 < side <= MAX_SIDE:
            raise LaunchError(f"{flag} {side}: each side must be 1 to {MAX_SIDE} pixels")
    output = Path(args.output)
    if not output.parent.is_dir():
        raise LaunchError(f"cannot write '{output}': the folder '{output.parent}' does not "
                          "exist")
    node = Node("snapshot", argv=[], parameter_services=False, space=keys.SIM)
    try:
        deadline = time.monotonic() + args.timeout
        try:
            world = args.world or find_world(node, deadline, args.timeout, "snapshot",
                                             SERVICE_TYPE, "--world")
        except (UsageError, SimNotFound) as exc:
            raise LaunchError(f"{exc}; is the sim running?") from None
        client = node.create_client(SERVICE_TYPE, f"/world/{world}/snapshot")
        if not client.wait_for_service(max(0.0, deadline - time.monotonic())):
            raise LaunchError(f"no sim with world '{world}' answered within "
                              f"{args.timeout:g} s (`launcher gz service -l` shows the "
                              "running ones)")
        request = node.message(f"{SERVICE_TYPE}_Request", width=args.width,
                               height=args.height, camera=args.camera, track=args.track)
        response = client.call(request, timeout=max(30.0, deadline - time.monotonic()))
        if not response.success:
            raise LaunchError(f"the sim could not render: {response.message}")
        output.write_bytes(bytes(response.png))
    finally:
        node.destroy_node()
    print(f"wrote {output} ({args.width}x{args.height}, world '{world}')")
    return 0


def main(argv: list[str]) -> int:
    return reported(lambda: take(argv))
