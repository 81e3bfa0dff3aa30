"""`launcher launch FILE [name:=value …]`."""

from __future__ import annotations

import argparse
import os
import re
import sys
from pathlib import Path

from launcher import compat
from launcher.bus import discovery
from launcher.cli import completion, launch_control, launch_stops, positive_number
from launcher.cli.components import BusLoader
from launcher.cli.lifecycle_bus import BusLifecycle
from launcher.cli.remote_graph import RemoteGraph
from launcher.cli.workspace import find_launch_file, hooked_environment, load_index
from launcher.description.action import LaunchDescription
from launcher.description.actions.arguments import check_required
from launcher.errors import DEBUG_VARIABLE, ParseError, UsageError
from launcher.frontend.builder import parse_file_text
from launcher.frontend.loader import load_file
from launcher.packages.index import PackageIndex
from launcher.runtime.custody import Custody
from launcher.runtime.logs import DEFAULT_LIMIT, log_root
from launcher.runtime.output import Printer
from launcher.runtime.service import LaunchService, default_environment
from launcher.schema import parse_bytes

_ASSIGNMENT = re.compile(r"^([A-Za-z_][A-Za-z0-9_\-./]*):=(.*)$", re.S)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = ("Run a launch file (.yaml, .xml or .py). Exit status: 0 when everything "
                          "ended cleanly; 1 for an invalid launch file, a failed action or a "
                          "process that exited with a non-zero code on its own; 130 after SIGINT "
                          "(Ctrl-C); 143 after SIGTERM.")
    parser.add_argument("file", metavar="[PKG] FILE",
                        help="the launch file; or a package and a launch file in it"
                        ).completer = completion.launch_targets  # type: ignore[attr-defined]
    parser.add_argument("arguments", nargs="*", metavar="name:=value", help="launch arguments"
                        ).completer = completion.launch_files  # type: ignore[attr-defined]
    parser.add_argument("-s", "--show-args", "--show-arguments", action="store_true",
                        help="list the launch arguments (also of included files) and exit")
    parser.add_argument("-p", "--print", "--print-description", action="store_true",
                        help="print the launch description as a tree and exit")
    parser.add_argument("-d", "--debug", action="store_true",
                        help="debug messages, and tracebacks with errors")
    parser.add_argument("--launch-prefix", default="",
                        help="put this command before every executable (e.g. 'valgrind')")
    parser.add_argument("-n", "--noninteractive", action="store_true",
                        help="run without a terminal: no colours")
    parser.add_argument("--duration", type=float, default=None, metavar="SECONDS",
                        help="shut the launch down cleanly after this many seconds")
    parser.add_argument("--sim-duration", type=positive_number, default=None,
                        metavar="SECONDS",
                        help="stop the sims at this many seconds of sim time, then shut the "
                             "launch down cleanly (sets LAUNCHER_SIM_STOP_AT, and "
                             "LAUNCHER_SIM_REPORT_DIR to the log folder's sim/)")
    parser.add_argument("--no-log-files", action="store_true",
                        help="write no log files (the screen, and `launcher logs`, still have "
                             "the output); also when LAUNCHER_NO_LOG_FILES or "
                             "RCL_LOGGING_DISABLE_FILE_WRITING is 1")
    parser.add_argument("--log-max-size", default=None, metavar="SIZE",
                        help="rotate each log file at this size (e.g. 50MiB; default 100MiB, "
                             "or LAUNCHER_LOG_MAX_SIZE); the last five are kept")
    parser.add_argument("--until", default=None, metavar="NAME",
                        help="shut the launch down when the process of this node name, "
                             "executable or label exits: exit status 0 when it exited with "
                             "0, else 1")


def parse_assignments(words: list[str]) -> dict[str, str]:
    values: dict[str, str] = {}
    for word in words:
        match = _ASSIGNMENT.match(word)
        if not match:
            raise UsageError(f"malformed launch argument '{word}': expected name:=value "
                             "(e.g. world_name:=arena.xml)")
        values[match.group(1)] = match.group(2)
    return values


def launch_path(args: argparse.Namespace, index: PackageIndex) -> Path:
    """`FILE`, or `PKG FILE` (the second word then is not a name:=value)."""
    if args.arguments and ":=" not in args.arguments[0] and not Path(args.file).is_file():
        package, file_name = args.file, args.arguments.pop(0)
        return find_launch_file(index, package, file_name)
    return Path(args.file)


def run(args: argparse.Namespace) -> int:
    """Read the file, show it if asked, else run it."""
    index = load_index()
    args.path = launch_path(args, index)
    description = load_file(args.path)
    configurations = parse_assignments(args.arguments)
    if args.show_args or args.print:
        return show(args, description, configurations, index)
    return launch(args, description, configurations, index)


def show(args: argparse.Namespace, description: LaunchDescription,
         configurations: dict[str, str], index: PackageIndex) -> int:
    """--show-args and --print: views of the description, nothing run."""
    from launcher.cli import views  # only for these views: start-up time

    if args.show_args:
        print(views.show_arguments(description, configurations, index), end="")
    else:
        print(views.print_tree(description, configurations, index), end="")
    return 0


def launch(args: argparse.Namespace, description: LaunchDescription,
           configurations: dict[str, str], index: PackageIndex) -> int:
    """Run the description on the user's graph, until it ends or is stopped."""
    check_required(description.actions, configurations)
    logs = log_settings(args)
    root: list = [description]
    if args.duration is not None:
        root += launch_stops.duration_stop(args.duration)
    service = launch_service(configurations, index, debug=args.debug,
                             noninteractive=args.noninteractive,
                             launch_prefix=args.launch_prefix, logs=logs,
                             controlled=getattr(args, "path", None) or Path(args.file))
    service.context.argv = [f"{name}:={value}" for name, value in configurations.items()]
    if args.sim_duration is not None:  # (the log folder is the service's)
        root += launch_stops.sim_duration_stop(args.sim_duration, service.context.environment,
                                               service.context.log_dir or log_root())
    until = launch_stops.UntilStop(args.until) if args.until is not None else None
    if until is not None:
        root += until.actions()
    code = service.run(LaunchDescription(root))
    if until is not None:
        until.check(code)
    return code


def log_settings(args: argparse.Namespace) -> tuple[bool, int]:
    """(whether to write log files, the size at which each rotates), from the options and
    the environment; a bad size is said before anything starts."""
    off = args.no_log_files or any(os.environ.get(name, "") not in ("", "0") for name in
                                   ("LAUNCHER_NO_LOG_FILES", "RCL_LOGGING_DISABLE_FILE_WRITING"))
    given = args.log_max_size if args.log_max_size is not None else \
        os.environ.get("LAUNCHER_LOG_MAX_SIZE")
    if given is None:
        return not off, DEFAULT_LIMIT
    what = "--log-max-size" if args.log_max_size is not None else "LAUNCHER_LOG_MAX_SIZE"
    try:
        return not off, parse_bytes(given, what)
    except ParseError as exc:
        raise UsageError(f"{exc.message} (the size at which each log file rotates: more "
                         "than 0)") from None


def launch_service(configurations: dict[str, str], index: PackageIndex, *, debug: bool = False,
                   noninteractive: bool = False, launch_prefix: str = "",
                   logs: tuple[bool, int] = (True, DEFAULT_LIMIT),
                   controlled: Path | None = None) -> LaunchService:
    """A launch service on the user's graph, with the workspace's hooks applied (what
    `launcher launch` and the launch tests run descriptions on); `logs`: whether to write
    log files, and their size limit; `controlled`: the launch file of a launch that answers
    `launcher ps` and its kin on the graph."""
    custody = Custody()
    custody.begin()  # before the hooks run: whatever they start is the launch's too
    environment = children_environment(index, debug)
    discovery.explicit_endpoints(environment)  # a bad LAUNCHER_ROUTER, ROS_DOMAIN_ID or
    discovery.socket_path(environment)  # run folder is said now, not at the first node
    service: LaunchService = LaunchService(
        custody=custody, printer=Printer(color=False) if noninteractive else None,
        log_root=log_root() if logs[0] else None, log_limit=logs[1], environment=environment,
        configurations=configurations,
        launch_prefix=launch_prefix, debug=debug, load_description=load_file,
        parse_text=parse_file_text, packages=index, loader=BusLoader(),
        lifecycle=BusLifecycle(environment),
        # the graph's router, unless one runs, once the first process that may join the graph
        # is spawned (so it starts while that one imports); a launch of system programs needs
        # none, and a node that opens its session sooner starts it itself
        on_graph=lambda: discovery.start(environment, wait=False),
        remote_graph=RemoteGraph(environment, custody.stamp),
        serve_control=None if controlled is None else launch_control.serving(
            environment, controlled.resolve(), lambda: service.context.log_dir),
    )
    return service


def children_environment(index: PackageIndex, debug: bool) -> dict[str, str]:
    """The launch's environment: the workspace's hooks applied, the shims and tools findable."""
    environment = hooked_environment(index, default_environment())
    if debug:  # the built-in nodes print tracebacks with their errors too
        environment[DEBUG_VARIABLE] = "1"
    compat.enable_for_children(environment)
    real = compat.real_node_apis(environment)
    if real:
        print(f"[INFO] [launch]: {real}", file=sys.stderr)
    tools_on_path(environment)
    compat.commands_for_children(environment)
    return environment


def tools_on_path(environment: dict[str, str]) -> None:
    """Put this launcher's own folder on the children's PATH (as sourcing a ROS setup file
    puts `ros2` there), so `cmd: launcher sim …` runs the same install."""
    folder = os.path.dirname(os.path.abspath(sys.argv[0]))
    if os.path.basename(sys.argv[0]) != "launcher" or not os.path.isdir(folder):
        folder = os.path.dirname(sys.executable)
    path = environment.get("PATH", "")
    if folder not in path.split(os.pathsep):
        environment["PATH"] = folder + (os.pathsep + path if path else "")
