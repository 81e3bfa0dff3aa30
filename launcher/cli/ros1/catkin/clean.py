"""`catkin clean`: remove build/ and devel/."""

from __future__ import annotations

import argparse
import shutil
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-w", "--workspace", default=".", help="the workspace")


def run(args: argparse.Namespace) -> int:
    workspace = Path(args.workspace).resolve()
    for name in ("build", "devel"):
        shutil.rmtree(workspace / name, ignore_errors=True)
    print(f"[clean] Removed build/ and devel/ of {workspace}")
    return 0
