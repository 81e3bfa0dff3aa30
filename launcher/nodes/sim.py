"""`sim [-v N] [-r] [-s] [--iterations N] [-z RATE|--rtf F|--lockstep] [WORLD]`: the world server.

The flags are `gz sim`'s: `-r` runs at start (otherwise paused until a control request),
`-s` is the server only: as `gz sim` (launcher's gz), the sim serves its web viewer (the GUI's
part: the world in a browser, on 127.0.0.1) unless `-s` is given; as `launcher sim`, only with
`--gui`. `-g` (the GUI alone) asks the running sim to serve its viewer and prints where.
The viewer's view is the world's `--camera NAME`, or follows `--track ENTITY`, or frames every
entity as `launcher sim snapshot` does.
`--iterations N` stops after N steps,
`-z RATE` paces at RATE steps per second (0: as fast as possible), `--rtf` paces at a
real-time factor instead (default: the world's <real_time_factor>, else 1), `--lockstep`
runs unpaced in lockstep with the nodes on sim time (launcher/bus/lockstep.py; also
LAUNCHER_SIM_LOCKSTEP=true, or a tick in seconds, where no pacing flag is given), `-v` sets the
verbosity (0 quiet … 4 debug; default 2, warnings). WORLD is an SDF or MJCF file: a path, a
file in a resource folder (MUJOCO_SIM_RESOURCE_PATH, GZ_SIM_RESOURCE_PATH, …) or a built-in
world (default: empty.sdf); `.j2` worlds are rendered with `--world-arg NAME=VALUE`.
`--keyframe NAME` starts from an MJCF keyframe, and resets return to it.
`--seed N` seeds the sensors' noise (default: LAUNCHER_SIM_SEED, else 0).
LAUNCHER_SIM_STOP_AT (s of sim time) ends the sim at the first step on or past it (exit 0);
with LAUNCHER_SIM_REPORT_DIR, the sim writes its report there as it exits (sim/report.py).
`--headless-rendering` and `--render-engine` are accepted.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launcher.arguments import Parser
from launcher.errors import UsageError, reported
from launcher.sim import viewer

if TYPE_CHECKING:
    from launcher.sim.report import SimReport

VERBOSITY = {0: 60, 1: 40, 2: 30, 3: 20, 4: 10}
LOCKSTEP_TICK = 0.01  # s of sim time a lockstep tick steps
LOCKSTEP_VARIABLE = "LAUNCHER_SIM_LOCKSTEP"  # as --lockstep, from a launch file's set_env
SEED_VARIABLE = "LAUNCHER_SIM_SEED"  # --seed's default (what a batch's job is given)
STOP_AT_VARIABLE = "LAUNCHER_SIM_STOP_AT"  # s of sim time at which the sim ends
REPORT_DIR_VARIABLE = "LAUNCHER_SIM_REPORT_DIR"  # where the sim writes its report at exit


def build_parser() -> Parser:
    """`sim`'s (and `gz sim`'s, `launcher sim`'s) command line."""
    parser = Parser(
        prog="sim", description=__doc__.split("\n")[0],
        epilog="A picture of a running world: launcher sim snapshot -o world.png (see -h there).")
    parser.add_argument("world", nargs="?", default=None, metavar="WORLD",
                        help="the world to run (default empty.sdf); with -g, the running "
                             "world's name, when more than one runs")
    parser.add_argument("-v", "--verbose", type=int, default=2, choices=range(5),
                        metavar="LEVEL", help="0 quiet, 1 errors, 2 warnings, 3 info, 4 debug")
    parser.add_argument("-r", "--run", action="store_true", help="run at start")
    parser.add_argument("-s", "--server", action="store_true",
                        help="server only: no web viewer (as `gz sim`, the viewer is served "
                             "unless -s is given)")
    parser.add_argument("-g", dest="gui_only", action="store_true",
                        help="the GUI alone: the running sim serves its web viewer; its "
                             "address is printed")
    parser.add_argument("--gui", action="store_true",
                        help=f"serve the world to a browser (MuJoCo Studio's web viewer, "
                             f"mujoco>=4) on 127.0.0.1 port {viewer.DEFAULT_PORT} (or the "
                             f"next free one); --gui=PORT for that port only")
    parser.add_argument("--gui-port", type=_port, default=None, help=argparse.SUPPRESS)
    parser.add_argument("--gui-host", default="127.0.0.1", metavar="ADDRESS",
                        help="the address the viewer listens on (default 127.0.0.1); "
                             "every request needs the graph's token, in the printed URL")
    parser.add_argument("--no-token", action="store_true",
                        help="no token check (for a viewer bound on purpose to a private "
                             "network): anyone who reaches the port can watch and pause the "
                             "world; LAUNCHER_NO_TOKEN=1 does the same")
    parser.add_argument("--gui-rate", type=float, default=viewer.DEFAULT_RATE, metavar="HZ",
                        help=f"how often the viewer gets the state (1 to {viewer.MAX_RATE:g}, "
                             f"default {viewer.DEFAULT_RATE:g})")
    view = parser.add_mutually_exclusive_group()
    view.add_argument("--camera", default="", metavar="NAME",
                      help="the web viewer's view: this camera of the world (as `launcher "
                           "sim snapshot --camera`)")
    view.add_argument("--track", default="", metavar="ENTITY",
                      help="the web viewer's view follows this entity, once it is there")
    parser.add_argument("--headless-rendering", action="store_true",
                        help="accepted: rendering is always headless (EGL)")
    parser.add_argument("--render-engine", default=None, metavar="ENGINE",
                        help="accepted and ignored: MuJoCo renders the pictures")
    parser.add_argument("--iterations", type=int, default=None, metavar="N",
                        help="stop after N steps")
    pace = parser.add_mutually_exclusive_group()
    pace.add_argument("-z", "--rate", type=float, default=None, metavar="RATE",
                      help="steps per second of wall time (0: unpaced)")
    pace.add_argument("--rtf", type=float, default=None, metavar="FACTOR",
                      help="real-time factor (1: real time, 0: unpaced)")
    pace.add_argument("--lockstep", action="store_true",
                      help="unpaced, as fast as the nodes on sim time follow: each tick of sim "
                           "time waits until they and the bridges have handled the one before; "
                           "time stands still while none is there")
    parser.add_argument("--lockstep-tick", type=float, default=LOCKSTEP_TICK, metavar="SECONDS",
                        help=f"sim time a lockstep tick steps (default {LOCKSTEP_TICK:g} s)")
    parser.add_argument("--world-arg", action="append", default=[], metavar="NAME=VALUE",
                        help="a value for a .j2 world template (repeatable)")
    parser.add_argument("--keyframe", default="", metavar="NAME",
                        help="start from this MJCF keyframe (<key name=NAME>); a reset "
                             "returns to it")
    parser.add_argument("--seed", type=int, default=None, metavar="N",
                        help=f"seed of the sensors' noise: the same seed, the same readings "
                             f"(default ${SEED_VARIABLE}, else 0)")
    parser.add_argument("--state-rate", type=float, default=50.0, metavar="HZ",
                        help="rate of pose/info and model_states in sim time")
    return parser


def lockstep_from_environment(unpaced_by_flags: bool) -> float | None:
    """LOCKSTEP_VARIABLE, as `--lockstep` (true, or a tick in seconds), where no pacing flag
    was given: what a launch file sets for the sim it starts (`set_env`)."""
    value = os.environ.get(LOCKSTEP_VARIABLE, "").strip().lower()
    if not unpaced_by_flags or value in ("", "0", "false", "no", "off"):
        return None
    if value in ("1", "true", "yes", "on"):
        return LOCKSTEP_TICK
    try:
        tick = float(value)
    except ValueError:
        tick = 0.0
    if not tick > 0:
        raise UsageError(f"{LOCKSTEP_VARIABLE}='{value}': expected true, false or a tick in "
                         "seconds (> 0)")
    return tick


def seed_from_environment() -> int:
    """SEED_VARIABLE, --seed's default."""
    value = os.environ.get(SEED_VARIABLE, "").strip()
    try:
        return int(value) if value else 0
    except ValueError:
        raise UsageError(f"{SEED_VARIABLE}='{value}': expected an integer seed (as --seed)"
                         ) from None


def stop_at_from_environment() -> float | None:
    """STOP_AT_VARIABLE: the sim time at which the sim ends, or None."""
    value = os.environ.get(STOP_AT_VARIABLE, "").strip()
    if not value:
        return None
    try:
        seconds = float(value)
    except ValueError:
        seconds = 0.0
    if not 0 < seconds < float("inf"):
        raise UsageError(f"{STOP_AT_VARIABLE}='{value}': expected seconds of sim time (> 0)")
    return seconds


def report_from_environment(world: Path, seed: int,
                            lockstep: float | None) -> SimReport | None:
    """The report REPORT_DIR_VARIABLE asks for (sim/report.py), its folder made now, so that
    a folder that cannot be is said at the start, not at the exit; None when not asked."""
    from launcher.sim.report import SimReport  # (as the sim's other parts, in run: start-up)

    value = os.environ.get(REPORT_DIR_VARIABLE, "")
    if not value:
        return None
    folder = Path(value).expanduser()
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UsageError(f"{REPORT_DIR_VARIABLE}='{value}': cannot make the folder "
                         f"({exc.strerror or exc}); expected a folder the sim can write in"
                         ) from None
    return SimReport(folder, str(world), seed, lockstep)


def pacing(rtf: float, lockstep: float | None) -> str:
    if lockstep is not None:
        return f"in lockstep with the nodes on sim time, {lockstep:g} s a tick"
    return "unpaced" if rtf == 0 else f"real-time factor {rtf:g}"


def parse(argv: list[str]) -> tuple[argparse.Namespace, list[str]]:
    ros: list[str] = []
    if "--ros-args" in argv:
        cut = argv.index("--ros-args")
        argv, ros = argv[:cut], argv[cut:]
    parser = build_parser()
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
    if not args.lockstep_tick > 0:
        parser.error(f"--lockstep-tick must be > 0 s, got {args.lockstep_tick:g}")
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


def main(argv: list[str] | None = None, gz: bool = False) -> int:
    """`gz` (as `gz sim`): the web viewer is served unless -s says server only."""
    args, ros = parse(sys.argv[1:] if argv is None else argv)
    if args.gui_only:  # the GUI alone: the running sim's viewer
        return reported(lambda: ask_for_view(args), "sim")
    if gz and not args.server:
        args.gui = True
    return reported(lambda: run(args, ros), "sim")


def ask_for_view(args: argparse.Namespace, timeout: float = 10.0) -> int:
    """`gz sim -g`: the running sim serves its web viewer (if it does not already); where."""
    import time

    from launcher.bus import keys
    from launcher.bus.node import Node
    from launcher.errors import LaunchError
    from launcher.nodes.create import SimNotFound, find_world

    node = Node("_launcher_gz_gui", argv=[], parameter_services=False, space=keys.SIM)
    try:
        deadline = time.monotonic() + timeout
        try:
            world = args.world or find_world(node, deadline, timeout, "gui",
                                             "mujoco_sim/srv/Gui", "`gz sim -g NAME`")
        except (UsageError, SimNotFound) as exc:
            raise LaunchError(f"{exc}; `gz sim -g` shows a running sim: start one with "
                              f"`gz sim -s WORLD`") from None
        client = node.create_client("mujoco_sim/srv/Gui", f"/world/{world}/gui")
        if not client.wait_for_service(max(0.5, deadline - time.monotonic())):
            raise LaunchError(f"no sim runs a world named '{world}' (`gz sim -g` with no "
                              f"name finds the one that runs)")
        answer = client.call(node.message("mujoco_sim/srv/Gui_Request",
                                          port=args.gui_port or 0), timeout)
    finally:
        node.destroy_node()
    if not answer.success:
        raise LaunchError(f"world '{world}': {answer.message}")
    print(f"[sim] the world '{world}' in a browser: {answer.url}", file=sys.stderr, flush=True)
    return 0


def run(args: argparse.Namespace, ros: list[str]) -> int:
    from launcher.bus import keys
    from launcher.bus.node import Node
    from launcher.sim.resources import find_world
    from launcher.sim.server import SimServer, install_signal_handlers
    from launcher.sim.transport import BusTransport
    from launcher.sim.world import World

    path = find_world(args.world or "empty.sdf")
    values = world_values(args.world_arg)
    lockstep = args.lockstep_tick if args.lockstep else \
        lockstep_from_environment(args.rate is None and args.rtf is None)
    seed = seed_from_environment() if args.seed is None else args.seed
    stop_at = stop_at_from_environment()
    report = report_from_environment(path, seed, lockstep)
    node = Node("sim", argv=ros, space=keys.SIM)  # off the ROS graph, as gz sim is
    node.get_logger().threshold = VERBOSITY[args.verbose]
    try:
        world = World.from_path(path, BusTransport(node), values, seed=seed)
        if args.keyframe:
            world.start_from(args.keyframe)
        timestep = world.model.opt.timestep
        default_rtf = world.real_time_factor if world.real_time_factor is not None else 1.0
        rtf = args.rtf if args.rtf is not None else \
            (args.rate * timestep if args.rate is not None else default_rtf)
        if lockstep is not None:
            rtf = 0.0
        server = SimServer(world, node, rtf, args.run, args.state_rate, lockstep)
        server.runner.stop_at, server.runner.report = stop_at, report
        # (before the viewer's URL: a stop after it is clean)
        install_signal_handlers(server.runner)
        log = node.get_logger()
        server.services.start_view = lambda port: start_view(args, log, port, world)
        if args.gui:
            view = start_view(args, log, args.gui_port, world)
            if view is not None:
                server.services.show(view)
        node.get_logger().info(
            f"world '{world.world_name}' from {path}: timestep {timestep} s, "
            f"{'running' if args.run else 'paused'}, "
            f"{pacing(rtf, lockstep)}")
        server.run(args.iterations)
    finally:
        node.destroy_node()
    if server.runner.view is not None:
        # Studio's native threads can outlive its close() by a moment and crash the
        # interpreter's teardown (SIGSEGV): with a viewer, the sim ends here, its output
        # flushed and its session closed already
        for stream in (sys.stdout, sys.stderr):
            stream.flush()
        os._exit(0)
    return 0


def start_view(args: argparse.Namespace, log: Any, port: int | None,
               world: Any) -> viewer.WebView | None:
    """The web viewer, or None (said why) when it cannot start: the sim runs on headless. On
    `port`, or without one on the first free one from 8080 (as more than one sim may run)."""
    from launcher.bus import listen_token

    token = None if args.no_token or listen_token.off() else listen_token.load()
    try:
        view = viewer.WebView.start(port, args.gui_host, args.gui_rate, log, args.camera,
                                    args.track, token)
        view.say_what_is_missing(world, log)
    except viewer.ViewerError as exc:
        log.error(f"{exc}; the sim runs on without it")
        return None
    if token is None:
        log.warning(f"web viewer: {listen_token.OFF_WARNING}")
    if args.gui_host not in ("127.0.0.1", "localhost", "::1"):
        log.warning(f"the web viewer listens on {args.gui_host}: anyone who can reach that "
                    f"address {'and holds the token ' if token else ''}can watch the world")
    # on the screen at any verbosity, as Gazebo's window would be
    print(f"[sim] the world in a browser: {view.url}", file=sys.stderr, flush=True)
    return view


if __name__ == "__main__":
    sys.exit(main())
