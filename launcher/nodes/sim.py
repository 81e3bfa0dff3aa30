"""`sim [-v LEVEL] [-r] [-s] [--iterations N] [-z RATE | --rtf FACTOR] [WORLD]`: the world server.

The flags are `gz sim`'s: `-r` runs at start (otherwise paused until a control request),
`-s` (server only) is accepted, as there is no GUI, `--iterations N` stops after N steps,
`-z RATE` paces at RATE steps per second (0: as fast as possible), `--rtf` paces at a
real-time factor instead (default: the world's <real_time_factor>, else 1), `-v` sets the
verbosity (0 quiet … 4 debug; default 2, warnings). WORLD is an SDF or MJCF file: a path, a
file in a resource folder (MUJOCO_SIM_RESOURCE_PATH, GZ_SIM_RESOURCE_PATH, …) or a built-in
world (default: empty.sdf); `.j2` worlds are rendered with `--world-arg NAME=VALUE`.
`--headless-rendering` and `--render-engine` are accepted; `-g` (Gazebo's GUI) says what
launcher offers instead.
"""

from __future__ import annotations

import argparse
import sys

from launcher.errors import UsageError, reported

VERBOSITY = {0: 60, 1: 40, 2: 30, 3: 20, 4: 10}


def parse(argv: list[str]) -> tuple[argparse.Namespace, list[str]]:
    ros: list[str] = []
    if "--ros-args" in argv:
        cut = argv.index("--ros-args")
        argv, ros = argv[:cut], argv[cut:]
    parser = argparse.ArgumentParser(
        prog="sim", description=__doc__.split("\n")[0],
        epilog="A picture of a running world: launcher sim snapshot -o world.png (see -h there).")
    parser.add_argument("world", nargs="?", default="empty.sdf", metavar="WORLD")
    parser.add_argument("-v", "--verbose", type=int, default=2, choices=range(5),
                        metavar="LEVEL", help="0 quiet, 1 errors, 2 warnings, 3 info, 4 debug")
    parser.add_argument("-r", "--run", action="store_true", help="run at start")
    parser.add_argument("-s", "--server", action="store_true", help="server only (always)")
    parser.add_argument("-g", "--gui", action="store_true",
                        help="Gazebo's GUI: not available; says what to use instead")
    parser.add_argument("--headless-rendering", action="store_true",
                        help="accepted: rendering is always headless (EGL)")
    parser.add_argument("--render-engine", default=None, metavar="ENGINE",
                        help="accepted and ignored: MuJoCo renders the pictures")
    parser.add_argument("--iterations", type=int, default=None, metavar="N")
    pace = parser.add_mutually_exclusive_group()
    pace.add_argument("-z", "--rate", type=float, default=None, metavar="RATE",
                      help="steps per second of wall time (0: unpaced)")
    pace.add_argument("--rtf", type=float, default=None, metavar="FACTOR",
                      help="real-time factor (1: real time, 0: unpaced)")
    parser.add_argument("--world-arg", action="append", default=[], metavar="NAME=VALUE",
                        help="a value for a .j2 world template (repeatable)")
    parser.add_argument("--state-rate", type=float, default=50.0, metavar="HZ",
                        help="rate of pose/info and model_states in sim time")
    args = parser.parse_args(argv)
    for name, value in (("--iterations", args.iterations), ("-z", args.rate),
                        ("--rtf", args.rtf)):
        if value is not None and value < 0:
            parser.error(f"{name} must be >= 0, got {value}")
    return args, ros


def world_values(pairs: list[str]) -> dict[str, str]:
    values = {}
    for pair in pairs:
        name, sep, value = pair.partition("=")
        if not sep or not name:
            raise UsageError(f"--world-arg expects NAME=VALUE, got '{pair}'")
        values[name] = value
    return values


GUI_INSTEAD = ("launcher has no Gazebo GUI: watch the world with `launcher sim snapshot -o "
               "world.png` (a picture of the running world), and the topics with `launcher "
               "gz topic -e -t TOPIC`")


def main(argv: list[str] | None = None) -> int:
    args, ros = parse(sys.argv[1:] if argv is None else argv)
    if args.gui:  # `gz sim -g` is the GUI alone: there is no server to run
        print(f"[sim] {GUI_INSTEAD}", file=sys.stderr, flush=True)
        return 0
    return reported(lambda: run(args, ros), "sim")


def run(args: argparse.Namespace, ros: list[str]) -> int:
    from launcher.bus import keys
    from launcher.bus.node import Node
    from launcher.sim.resources import find_world
    from launcher.sim.server import SimServer, install_signal_handlers
    from launcher.sim.transport import BusTransport
    from launcher.sim.world import World

    path = find_world(args.world)
    values = world_values(args.world_arg)
    node = Node("sim", argv=ros, space=keys.SIM)  # off the ROS graph, as gz sim is
    node.get_logger().threshold = VERBOSITY[args.verbose]
    try:
        world = World.from_path(path, BusTransport(node), values)
        timestep = world.model.opt.timestep
        default_rtf = world.real_time_factor if world.real_time_factor is not None else 1.0
        rtf = args.rtf if args.rtf is not None else \
            (args.rate * timestep if args.rate is not None else default_rtf)
        server = SimServer(world, node, rtf, args.run, args.state_rate)
        install_signal_handlers(server)
        node.get_logger().info(
            f"world '{world.world_name}' from {path}: timestep {timestep} s, "
            f"{'running' if args.run else 'paused'}, "
            f"{'unpaced' if rtf == 0 else f'real-time factor {rtf:g}'}")
        server.run(args.iterations)
    finally:
        node.destroy_node()
    return 0


if __name__ == "__main__":
    sys.exit(main())
