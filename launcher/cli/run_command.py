"""`launcher run PKG EXECUTABLE [ARGS…] [--ros-args …]`: one executable of a package, as
`ros2 run` (and ROS 1's `rosrun`) does, with the workspace's hooks applied and rclpy, rospy
and the message modules importable (where no real ones are installed).

The executable replaces this process (exec), so signals, the exit status and the terminal
are its own, and nothing of launcher stays behind it. The graph's router is started first
if none runs (rmw_zenoh would make you start `rmw_zenohd` by hand).
"""

from __future__ import annotations

import argparse
import os
import shlex
import sys

from launcher import compat
from launcher.errors import LaunchError, UsageError

USAGE = "usage: launcher run [--prefix PREFIX] [--debug] PACKAGE EXECUTABLE [ARGS…]"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Its words, described for the docs and tab completion (a run takes them as typed:
    run_run leaves every word after EXECUTABLE to it)."""
    from launcher.cli import completion

    parser.add_argument("--prefix", metavar="PREFIX",
                        help="run it under PREFIX (e.g. 'gdb -ex run --args')")
    parser.add_argument("--debug", action="store_true", help="tracebacks with errors")
    parser.add_argument("package", help="the package").completer = completion.packages  # type: ignore[attr-defined]
    parser.add_argument("executable", help="its executable").completer = completion.executables  # type: ignore
    parser.add_argument("arguments", nargs=argparse.REMAINDER, help="the executable's own")


def run_run(argv: list[str]) -> int:
    prefix: list[str] = []
    debug = False
    words = list(argv)
    while words and words[0].startswith("-"):
        option = words.pop(0)
        if option in ("-h", "--help"):
            print(USAGE + "\n\nRun an executable of a package (as `ros2 run`/`rosrun`); "
                  "everything after EXECUTABLE is its own.\n  --prefix PREFIX  run it under "
                  "PREFIX (e.g. 'gdb -ex run --args')\n  --debug          tracebacks with "
                  "errors")
            return 0
        if option == "--debug":
            debug = True
        elif option == "--prefix" and words:
            prefix = shlex.split(words.pop(0))
        elif option.startswith("--prefix="):
            prefix = shlex.split(option.split("=", 1)[1])
        else:
            raise UsageError(f"unknown option '{option}'\n{USAGE}")
    if len(words) < 2:
        raise UsageError(f"expected a package and an executable\n{USAGE}")
    package_name, executable_name, rest = words[0], words[1], words[2:]
    from launcher.bus import discovery
    from launcher.cli.launch_command import children_environment
    from launcher.cli.workspace import load_index
    from launcher.packages.executables import find_executable

    index = load_index()
    executable = find_executable(index.get(package_name), executable_name)
    environment = executable.environment(children_environment(index, debug))
    real = compat.real_node_apis(environment)
    if real:
        print(f"[INFO] [run]: {real}", file=sys.stderr)
    discovery.start(environment)
    command = [*prefix, *executable.argv, *rest]
    sys.stdout.flush()
    try:
        os.execvpe(command[0], command, environment)
    except OSError as exc:
        raise LaunchError(f"cannot run {' '.join(map(shlex.quote, command))}: "
                          f"{exc.strerror}") from None
    return 0  # not reached


def main(argv: list[str], prog: str = "") -> int:
    """The words after `run` (a tool: cli/commands.py)."""
    return run_run(argv)
