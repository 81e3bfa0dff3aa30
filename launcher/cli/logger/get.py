"""`launcher logger get`: a logger's level."""

from __future__ import annotations

import argparse

from launcher.cli.logger.client import NAMES, call_node, logger_name


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node (/talker)")
    parser.add_argument("logger", nargs="?", help="the logger (the node's own by default)")


def run(args: argparse.Namespace) -> int:
    name = logger_name(args.node, args.logger)
    answer = call_node(args.node, "GetLoggerLevels", {"names": [name]})
    level = answer.levels[0].level  # type: ignore[attr-defined]
    print(f"{name}: {NAMES.get(level, level)}")
    return 0
