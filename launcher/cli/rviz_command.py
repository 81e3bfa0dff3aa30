"""`launcher rviz2-layout CONFIG.rviz [-o layout.json]`: an rviz config as a Foxglove layout
(nodes/rviz/layout.py), for users who want the file alone; the displays with no mapping are
listed."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("config", help="the .rviz file (rviz2's, or ROS 1 rviz's)")
    parser.add_argument("-o", "--output", default=None,
                        help="the layout to write (default: the config's name, .json, here)")


def run(args: argparse.Namespace) -> int:
    from launcher.nodes.rviz import layout

    config = Path(args.config)
    made, unmapped = layout.convert(layout.read(config))
    target = Path(args.output) if args.output else Path(f"{config.stem}.json")
    layout.write(made, target)
    panels = ", ".join(key.split("!")[0] for key in made["configById"])
    print(f"{target}: {panels}")
    if unmapped:
        print(f"not shown (no Foxglove panel for them): {', '.join(unmapped)}",
              file=sys.stderr)
    return 0
