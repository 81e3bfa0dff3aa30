"""`launcher logs NAME [-f] [--launch LAUNCH]`: one process's output, as the running launch
keeps its latest lines (the whole is in the launch's log folder)."""

from __future__ import annotations

import argparse
import sys
import time

from launcher.bus.launches import Launches
from launcher.cli.process_command import add_process

FOLLOW = 0.2  # seconds between asks of -f


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = ("Print one process's output from a running launch: the latest lines "
                          "the launch keeps (2,000 at most); with -f, then what it prints next, "
                          "until Ctrl-C.")
    add_process(parser)
    parser.add_argument("-f", "--follow", action="store_true",
                        help="keep printing what it prints")


def run(args: argparse.Namespace) -> int:
    launches = Launches()
    try:
        launch, row = launches.pick(args.name, args.launch)
        after = 0
        while True:
            answer = launches.output(launch, row.name, after)
            if after and answer.first > after + 1:
                print(f"[launcher logs: {answer.first - after - 1} lines came too fast to "
                      "show; the log folder has them]", file=sys.stderr)
            if answer.lines:
                sys.stdout.write("".join(line + "\n" for line in answer.lines))
                sys.stdout.flush()
            after = max(after, answer.last)
            if not args.follow:
                return 0
            time.sleep(FOLLOW)
    finally:
        launches.close()
