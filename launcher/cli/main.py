"""`launcher COMMAND …`: parse argv, run the command, print one clean message on failure."""

from __future__ import annotations

import argparse
import sys

from launcher import __version__
from launcher.cli import env_command, launch_command, pkg_command
from launcher.errors import LaunchError


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="launcher", description="ROS 2-style launch files for simulated robots.")
    parser.add_argument("--version", action="version", version=f"launcher {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    launch_command.add_parser(commands)
    pkg_command.add_parser(commands)
    env_command.add_parser(commands)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    debug = getattr(args, "debug", False)
    try:
        return int(args.run(args) or 0)
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
