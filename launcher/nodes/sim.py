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
import os
import sys
from typing import Any

from launcher.errors import UsageError, reported
from launcher.sim import viewer

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
    parser.add_argument("-g", dest="gui_only", action="store_true",
                        help="Gazebo's GUI alone: not available; says what to use instead")
    parser.add_argument("--gui", action="store_true",
                        help=f"serve the world to a browser (MuJoCo Studio's web viewer, "
                             f"mujoco>=4) on 127.0.0.1; --gui=PORT for another port than "
                             f"{viewer.DEFAULT_PORT}")
    parser.add_argument("--gui-port", type=_port, default=viewer.DEFAULT_PORT,
                        help=argparse.SUPPRESS)
    parser.add_argument("--gui-host", default="127.0.0.1", metavar="ADDRESS",
                        help="the address the viewer listens on (default 127.0.0.1). The "
                             "viewer has no authentication: another address lets anyone who "
                             "can reach it watch the world and read the model")
    parser.add_argument("--gui-rate", type=float, default=viewer.DEFAULT_RATE, metavar="HZ",
                        help=f"how often the viewer gets the state (1 to {viewer.MAX_RATE:g}, "
                             f"default {viewer.DEFAULT_RATE:g})")
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
    # --gui=PORT; a bare --gui takes no value (it would take the world's name)
    argv = [w for a in argv for w in (["--gui", "--gui-port", a[6:]]
                                      if a.startswith("--gui=") else [a])]
    args = parser.parse_args(argv)
    if not 1 <= args.gui_rate <= viewer.MAX_RATE:
        parser.error(f"--gui-rate must be between 1 and {viewer.MAX_RATE:g} Hz, "
                     f"got {args.gui_rate:g}")
    for name, value in (("--iterations", args.iterations), ("-z", args.rate),
                        ("--rtf", args.rtf)):
        if value is not None and value < 0:
            parser.error(f"{name} must be >= 0, got {value}")
    return args, ros


def _port(text: str) -> int:
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a port number (1-65535), got "
                                         f"'{text}'") from None
    if not 1 <= port <= 65535:
        raise argparse.ArgumentTypeError(f"expected a port number (1-65535), got {port}")
    return port


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
    if args.gui_only:  # `gz sim -g` is the GUI alone: there is no server to run
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
    view = None
    node.get_logger().threshold = VERBOSITY[args.verbose]
    try:
        world = World.from_path(path, BusTransport(node), values)
        timestep = world.model.opt.timestep
        default_rtf = world.real_time_factor if world.real_time_factor is not None else 1.0
        rtf = args.rtf if args.rtf is not None else \
            (args.rate * timestep if args.rate is not None else default_rtf)
        server = SimServer(world, node, rtf, args.run, args.state_rate)
        install_signal_handlers(server)  # (before the viewer's URL: a stop after it is clean)
        if args.gui:
            server.view = view = start_view(args, node.get_logger())
        node.get_logger().info(
            f"world '{world.world_name}' from {path}: timestep {timestep} s, "
            f"{'running' if args.run else 'paused'}, "
            f"{'unpaced' if rtf == 0 else f'real-time factor {rtf:g}'}")
        server.run(args.iterations)
    finally:
        node.destroy_node()
    if view is not None:
        # Studio's native threads can outlive its close() by a moment and crash the
        # interpreter's teardown (SIGSEGV): with a viewer, the sim ends here, its output
        # flushed and its session closed already
        for stream in (sys.stdout, sys.stderr):
            stream.flush()
        os._exit(0)
    return 0


def start_view(args: argparse.Namespace, log: Any) -> viewer.WebView | None:
    """The web viewer, or None (said why) when it cannot start: the sim runs on headless."""
    try:
        view = viewer.WebView.start(args.gui_port, args.gui_host, args.gui_rate)
    except viewer.ViewerError as exc:
        log.error(f"{exc}; the sim runs on without it")
        return None
    if args.gui_host not in ("127.0.0.1", "localhost", "::1"):
        log.warning(f"the web viewer listens on {args.gui_host}: it has no authentication, "
                    f"anyone who can reach that address can watch the world")
    # on the screen at any verbosity, as Gazebo's window would be
    print(f"[sim] the world in a browser: {view.url}", file=sys.stderr, flush=True)
    return view


if __name__ == "__main__":
    sys.exit(main())
