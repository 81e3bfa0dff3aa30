"""`catkin init`: mark the workspace."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-w", "--workspace", default=".", help="the workspace")


def run(args: argparse.Namespace) -> int:
    workspace = Path(args.workspace).resolve()
    (workspace / ".catkin_tools").mkdir(exist_ok=True)
    print(f"Initialized new catkin workspace in `{workspace}`")
    return 0
