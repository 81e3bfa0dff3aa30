"""`roslaunch [options] [package] <filename> [arg_name:=value …]`, as ROS 1's roslaunch finds
its file (a path, or a file anywhere in the package) and says so when it cannot, then runs it
as `launcher launch` does. roslaunch's display options are taken: `--screen` (every node's
output is on the screen already), `--wait` (the graph needs no master to wait for), `-v`,
`--ros-args` (the file's arguments); `--nodes`, `--args`, `--find-node`, `--files` and
`--dump-params` print roslaunch's views instead of running (roslaunch_views.py)."""

from __future__ import annotations

import argparse
import os
from pathlib import Path
from typing import Any

from launcher.arguments import Parser
from launcher.errors import LaunchError, UsageError


def parser(prog: str = "roslaunch") -> Parser:
    p = Parser(prog=prog, usage="roslaunch [options] [package] <filename> [arg_name:=value...]"
               "\n       roslaunch [options] <filename> [<filename>...] [arg_name:=value...]",
               description="Run a ROS 1 launch file (or a ROS 2 one) on launcher's graph.")
    p.add_argument("words", nargs="*", help=argparse.SUPPRESS)
    p.add_argument("--screen", action="store_true",
                   help="force output of all local nodes to screen (they print there already)")
    p.add_argument("--wait", action="store_true",
                   help="wait for master to start (the graph needs none: no wait)")
    p.add_argument("-v", dest="verbose", action="store_true", help="verbose printing")
    p.add_argument("--ros-args", dest="show_args", action="store_true",
                   help="display the arguments of the launch file and exit")
    p.add_argument("--nodes", action="store_true",
                   help="print the name of every node the file(s) start, and exit")
    p.add_argument("--args", dest="node_args", metavar="NODE_NAME",
                   help="print the command line of a node, and exit")
    p.add_argument("--find-node", metavar="NODE_NAME",
                   help="print the launch file that declares a node, and exit")
    p.add_argument("--files", action="store_true",
                   help="print the launch files the launch reads, and exit")
    p.add_argument("--dump-params", action="store_true",
                   help="print the parameters the launch sets, as YAML, and exit")
    p.add_argument("--duration", type=float, default=None, metavar="SECONDS",
                   help="shut the launch down cleanly after this many seconds (launcher's)")
    p.add_argument("--debug", action="store_true", help="tracebacks with errors (launcher's)")
    for name in ("--core", "--local", "--disable-title", "--no-summary", "--skip-log-check",
                 "--sigint-timeout", "--sigterm-timeout"):
        p.add_argument(name, action="store_true" if "timeout" not in name else "store",
                       help=argparse.SUPPRESS)
    return p


def main(argv: list[str], prog: str = "roslaunch") -> int:
    args, extra = parser(prog).parse_known_args(argv)
    words = [*args.words, *extra]
    flags = [w for w in words if w.startswith("-")]
    if flags:
        parser(prog).error(f"unrecognized arguments: {' '.join(flags)}")
    files, assignments = _split(words)
    from launcher.cli import launch_command
    from launcher.cli.ros1 import roslaunch_views
    from launcher.cli.workspace import load_index

    index = load_index()
    paths = resolve(files, index)
    configurations = launch_command.parse_assignments(assignments)
    if any(getattr(args, view) for view in roslaunch_views.VIEWS):
        return roslaunch_views.show(args, combined(paths), configurations, index)
    launch = launch_options(paths[0])  # (launch's defaults: its options as it has them)
    launch.arguments, launch.show_args = assignments, args.show_args
    launch.debug, launch.duration = args.debug, args.duration
    if len(paths) == 1 or args.show_args:
        return launch_command.run(launch)
    return launch_command.launch(launch, combined(paths), configurations, index)


def launch_options(path: Path) -> argparse.Namespace:
    """`launcher launch PATH`'s options, each at its default."""
    from launcher.arguments import Parser
    from launcher.cli import launch_command

    options = Parser(prog="launcher launch")
    launch_command.add_arguments(options)
    return options.parse_args([str(path)])


def combined(paths: list[Path]) -> Any:
    """The files as one launch, as roslaunch loads several into one config: each file in a
    scope of its own (its args and settings its own), the arguments given to all."""
    from launcher.description.action import LaunchDescription
    from launcher.description.actions.group import GroupAction
    from launcher.frontend.loader import load_file

    if len(paths) == 1:
        return load_file(paths[0])
    return LaunchDescription([GroupAction(actions=[load_file(p)]) for p in paths])


def _split(words: list[str]) -> tuple[list[str], list[str]]:
    files = [w for w in words if ":=" not in w]
    assignments = [w for w in words if ":=" in w]
    if not files:
        raise UsageError("roslaunch: you must specify at least one input file")
    return files, assignments


def resolve(files: list[str], index: object) -> list[Path]:
    """The launch files, found as roslaunch's rlutil.resolve_launch_arguments finds them."""
    from launcher.packages.index import PackageIndex, PackageNotFound

    assert isinstance(index, PackageIndex)
    if os.path.isfile(files[0]):  # then every word is a file (rlutil.resolve_launch_arguments)
        for name in files[1:]:
            if not os.path.isfile(name):
                raise LaunchError(f"RLException: [{name}] is not a launch file name (no such "
                                  f"file: {os.path.abspath(name)})")
        return [Path(name) for name in files]
    if len(files) < 2:
        raise LaunchError(f"RLException: [{files[0]}] is neither a launch file in package "
                          f"nor is it a launch file name (no such file: "
                          f"{os.path.abspath(files[0])})")
    package_name, file_name = files[0], files[1]
    try:
        package = index.get(package_name)
    except PackageNotFound as exc:
        raise LaunchError(f"RLException: [{package_name}] is not a package or launch file "
                          f"name; {str(exc).split('; ', 1)[0]}") from None
    matches = sorted(p for p in package.path.rglob(file_name) if p.is_file())
    if len(matches) > 1:
        listed = "".join(f"\n  {m}" for m in matches)
        raise LaunchError(f"RLException: multiple files named [{file_name}] in package "
                          f"[{package_name}]:{listed}\nPlease specify full path instead")
    if not matches:
        from launcher.errors import did_you_mean

        have = sorted({p.name for pattern in ("*.launch", "*.launch.*", "*.xml")
                       for p in package.path.rglob(pattern)})
        raise LaunchError(f"RLException: [{file_name}] is neither a launch file in package "
                          f"[{package_name}] nor is [{package_name}] a launch file name"
                          f"{did_you_mean(file_name, have)}; the package ({package.path}) "
                          f"has: {', '.join(have) or 'no launch files'}")
    return matches[:1]
