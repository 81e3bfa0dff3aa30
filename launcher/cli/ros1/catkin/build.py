"""`catkin build`: catkin_make's work on the workspace's packages."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("packages", nargs="*", help="only these packages")
    parser.add_argument("-w", "--workspace", default=".", help="the workspace (default: here)")


def run(args: argparse.Namespace) -> int:
    from launcher.cli.ros1 import catkin_make

    workspace = Path(args.workspace).resolve()
    return catkin_make.main(["-C", str(workspace),
                             *(["--pkg", *args.packages] if args.packages else [])], "catkin")
