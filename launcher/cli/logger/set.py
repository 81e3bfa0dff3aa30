"""`launcher logger set`: set a logger's level."""

from __future__ import annotations

import argparse

from launcher.cli.logger.client import NAMES, call_node, logger_name
from launcher.errors import LaunchError, UsageError

LEVELS = {"unset": 0, "debug": 10, "info": 20, "warn": 30, "warning": 30, "error": 40,
          "fatal": 50}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node")
    parser.add_argument("level", help="debug, info, warn, error, fatal or unset (or a number)")
    parser.add_argument("logger", nargs="?", help="the logger (the node's own by default)")


def run(args: argparse.Namespace) -> int:
    text = args.level.lower()
    level = LEVELS.get(text, int(text) if text.isdigit() else None)
    if level is None:
        raise UsageError(f"unknown level '{args.level}': expected one of "
                         f"{', '.join(k for k in LEVELS if k != 'warning')}")
    name = logger_name(args.node, args.logger)
    answer = call_node(args.node, "SetLoggerLevels", {"levels": [{"name": name, "level": level}]})
    result = answer.results[0]  # type: ignore[attr-defined]
    if not result.successful:
        raise LaunchError(f"{args.node} refused: {result.reason}")
    print(f"{name}: {NAMES.get(level, level)}")
    return 0
