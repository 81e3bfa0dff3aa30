"""`launcher stop|start|restart NAME [--launch LAUNCH]`: one process of a running launch, with
its own stop rules (its signal sequence; a container's composable nodes loaded again)."""

from __future__ import annotations

import argparse

from launcher.bus.launches import Launches

HELP = {"stop": "Stop one process of a running launch, as the launch stops it (SIGINT, then "
                "SIGTERM and SIGKILL after its timeouts). It is not a crash: no respawn, and a "
                "required process does not end the launch; it stays stopped until started.",
        "start": "Start a stopped or exited process of a running launch again, with the same "
                 "command, environment and rules.",
        "restart": "Stop one process of a running launch (its own signal sequence), then start "
                   "it again; a container's composable nodes are loaded again."}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verb = parser.prog.split()[-1]
    parser.description = HELP.get(verb)
    add_process(parser)


def add_process(parser: argparse.ArgumentParser) -> None:
    """NAME and --launch: one process of the running launches (logs takes them too)."""
    parser.add_argument("name", metavar="NAME",
                        help="the process: its label (talker-1), or its node's or executable's "
                             "name when that names one process")
    parser.add_argument("--launch", default=None, metavar="LAUNCH",
                        help="the launch, when several run (its file's name, or its pid)")


def run(args: argparse.Namespace) -> int:
    launches = Launches()
    try:
        launch, row = launches.pick(args.name, args.launch)
        print(launches.act(launch, row.name, args.command))
    finally:
        launches.close()
    return 0
