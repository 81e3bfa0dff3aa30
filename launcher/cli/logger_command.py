"""`launcher logger get|set NODE …`: a node's logger levels through its logger service
(`~/get_logger_levels`, `~/set_logger_levels`, which rclpy offers with
enable_logger_service=True)."""

from __future__ import annotations

import argparse

from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.errors import LaunchError, UsageError

LEVELS = {"unset": 0, "debug": 10, "info": 20, "warn": 30, "warning": 30, "error": 40,
          "fatal": 50}
NAMES = {0: "UNSET", 10: "DEBUG", 20: "INFO", 30: "WARN", 40: "ERROR", 50: "FATAL"}


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("logger", help="a node's logger levels: get, set")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    get = verbs.add_parser("get", help="a logger's level")
    get.add_argument("node", help="the node (/talker)")
    get.add_argument("logger", nargs="?", help="the logger (the node's own by default)")
    get.set_defaults(run=run_get)
    put = verbs.add_parser("set", help="set a logger's level")
    put.add_argument("node", help="the node")
    put.add_argument("level", help="debug, info, warn, error, fatal or unset (or a number)")
    put.add_argument("logger", nargs="?", help="the logger (the node's own by default)")
    put.set_defaults(run=run_set)


def _call(node: str, service: str, values: dict) -> object:
    client_node = Node("_launcher_logger", argv=[], parameter_services=False)
    try:
        client = client_node.create_client(f"rcl_interfaces/srv/{service}",
                                           f"{node}/{_snake(service)}")
        if not client.wait_for_service(3.0):
            raise LaunchError(f"{node} offers no {_snake(service)} service: start it with "
                              "enable_logger_service=True (rclpy) to change its levels")
        return client.call(build(f"rcl_interfaces/srv/{service}_Request", values), 5.0)
    finally:
        client_node.destroy_node()


def _snake(service: str) -> str:
    return {"GetLoggerLevels": "get_logger_levels",
            "SetLoggerLevels": "set_logger_levels"}[service]


def _logger(node: str, given: str | None) -> str:
    return given or node.strip("/").replace("/", ".")


def run_get(args: argparse.Namespace) -> int:
    name = _logger(args.node, args.logger)
    answer = _call(args.node, "GetLoggerLevels", {"names": [name]})
    level = answer.levels[0].level  # type: ignore[attr-defined]
    print(f"{name}: {NAMES.get(level, level)}")
    return 0


def run_set(args: argparse.Namespace) -> int:
    text = args.level.lower()
    level = LEVELS.get(text, int(text) if text.isdigit() else None)
    if level is None:
        raise UsageError(f"unknown level '{args.level}': expected one of "
                         f"{', '.join(k for k in LEVELS if k != 'warning')}")
    name = _logger(args.node, args.logger)
    answer = _call(args.node, "SetLoggerLevels", {"levels": [{"name": name, "level": level}]})
    result = answer.results[0]  # type: ignore[attr-defined]
    if not result.successful:
        raise LaunchError(f"{args.node} refused: {result.reason}")
    print(f"{name}: {NAMES.get(level, level)}")
    return 0
