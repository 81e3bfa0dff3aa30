"""`launcher COMMAND …`: parse argv, run the command, print one clean message on failure.

Only the module of the command being run is imported (start-up time is benchmarked); the
others are listed for `--help` from this table.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Callable
from typing import Any

from launcher import __version__
from launcher.errors import LaunchError

COMMANDS = {
    "launch": ("launcher.cli.launch_command", "run a launch file"),
    "pkg": ("launcher.cli.pkg_command", "packages: list, find, create"),
    "env": ("launcher.cli.env_command", "print the environment the workspace's hooks make"),
    "topic": ("launcher.cli.topic_command", "topics: list, echo, pub, hz, info"),
    "bag": ("launcher.cli.bag_command", "record and play rosbag2 (MCAP) bags"),
    "service": ("launcher.cli.service_command", "services: list, call"),
    "node": ("launcher.cli.node_command", "nodes: list, info"),
    "param": ("launcher.cli.param_command", "parameters of a running node: list, get, set"),
    "sim": ("launcher.cli.sim_command", "run the MuJoCo world server"),
    "gz": ("launcher.cli.gz_command", "Gazebo's commands (sim, topic, service, model)"),
}


def build_parser(selected: str | None) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="launcher", description="ROS 2-style launch files for simulated robots.")
    parser.add_argument("--version", action="version", version=f"launcher {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name, (module, helptext) in COMMANDS.items():
        if name == selected:
            importlib.import_module(module).add_parser(commands)
        else:
            commands.add_parser(name, help=helptext)
    return parser


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["sim"]:  # every flag after it is the sim's own (gz sim's), -h included
        from launcher.cli.sim_command import run_sim

        return run_sim(argv[1:])
    if argv[:1] == ["gz"]:  # Gazebo's own flags, -h included
        from launcher.cli.gz_command import run_gz

        return _reported(run_gz, [a for a in argv[1:] if a != "--debug"], "--debug" in argv)
    selected = next((word for word in argv if not word.startswith("-")), None)
    parser = build_parser(selected if selected in COMMANDS else None)
    if selected == "launch" and argv[0] == "launch":
        # `name:=value` may come before or after options (`--duration 10 drive:=false`)
        commands = next(a for a in parser._actions
                        if isinstance(a, argparse._SubParsersAction))
        args = commands.choices["launch"].parse_intermixed_args(argv[1:])
    else:
        args = parser.parse_args(argv)
    return _reported(lambda _: args.run(args), [], getattr(args, "debug", False))


def _reported(run: Callable[[list[str]], Any], argv: list[str], debug: bool) -> int:
    """Run a command; a LaunchError is one line on stderr (the traceback with --debug)."""
    try:
        return int(run(argv) or 0)
    except LaunchError as exc:
        if debug:
            import traceback  # only with --debug: start-up time

            traceback.print_exc()
        print(f"error: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        return 130
    except Exception as exc:  # a bug: still one clean line, the trace with --debug
        if debug:
            raise
        print(f"error: internal error: {type(exc).__name__}: {exc} "
              "(run with --debug for the traceback)", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
