"""`launcher topic echo`: print the messages on a topic."""

from __future__ import annotations

import argparse
import sys
import threading
from typing import Any

from launcher.bus.session import open_session
from launcher.cli import completion, positive_count, positive_number, qos_options
from launcher.cli.graph_options import add_sim_option, space_of
from launcher.cli.topic.lookup import topic_name, type_of
from launcher.errors import LaunchError, UsageError, did_you_mean


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("topic", help="the topic").completer = completion.topics  # type: ignore[attr-defined]
    parser.add_argument("type", nargs="?", help="the message type (default: as published)")
    parser.add_argument("--once", action="store_true", help="print one message and exit")
    parser.add_argument("--field", help="print only this field (a.b.c)")
    parser.add_argument("--csv", action="store_true", help="one comma-separated line each")
    parser.add_argument("--timeout", type=positive_number, default=None, metavar="SECONDS",
                        help="stop after this many seconds; exit 1 if nothing arrived")
    parser.add_argument("--no-arr", action="store_true",
                        help="print arrays and sequences as their type and length")
    parser.add_argument("--no-str", action="store_true", help="print strings as their length")
    parser.add_argument("--flow-style", action="store_true",
                        help="YAML's flow style: each message on one line")
    parser.add_argument("--filter", metavar="EXPR", dest="filter_expr",
                        help="print only messages for which EXPR is true; the message is `m` "
                             "(m.data == 'hi', m.linear.x > 0.5); the same restricted "
                             "expressions as $(eval)")
    parser.add_argument("--raw", action="store_true",
                        help="the serialized message (CDR bytes) instead of its fields")
    length = parser.add_mutually_exclusive_group()
    length.add_argument("-l", "--truncate-length", type=positive_count, default=128,
                        metavar="N", help="cut strings and arrays to N items (default 128)")
    length.add_argument("-f", "--full-length", action="store_true",
                        help="print strings and arrays whole")
    qos_options.add(parser, default="best_available")
    add_sim_option(parser, "topics")


def _pick(data: Any, field: str | None) -> Any:
    for part in (field.split(".") if field else []):
        if not isinstance(data, dict) or part not in data:
            raise UsageError(f"--field: no field '{part}'"
                             f"{did_you_mean(part, data if isinstance(data, dict) else [])}")
        data = data[part]
    return data


def _csv(data: Any) -> str:
    if isinstance(data, dict):
        return ",".join(_csv(v) for v in data.values())
    if isinstance(data, list):
        return ",".join(_csv(v) for v in data)
    return str(data)


def run(args: argparse.Namespace) -> int:
    import yaml

    from launcher.bus.node import Node

    accept = _filter(args.filter_expr)
    session = open_session("client")
    topic = topic_name(args.topic)
    type_name = type_of(session, topic, args.type, space_of(args))
    node = Node("_launcher_topic_echo", argv=[], parameter_services=False, session=session,
                space=space_of(args))
    received = threading.Event()
    shown = echo_options(args)
    shown_count = [0]  # printed so far (rostopic's `-n COUNT` stops at COUNT)

    def show(message: Any) -> None:
        if args.raw:
            text = f"{bytes(message)!r}\n"
        else:
            if accept is not None and not accept(message):
                return
            data = _pick(shown(message, type_name), args.field)
            if args.csv:
                text = _csv(data)
            else:
                text = yaml.safe_dump(data, default_flow_style=args.flow_style,
                                      sort_keys=False, allow_unicode=True,
                                      width=float("inf")) \
                    if isinstance(data, dict | list) else f"{data}\n"
        received.set()
        print(text if args.csv else text + "---", flush=True)
        shown_count[0] += 1
        if args.once or shown_count[0] == getattr(args, "count", 0):
            node.shutdown()

    node.create_subscription(type_name, topic, show, qos_options.chosen(args), raw=args.raw)
    node.spin(args.timeout)
    node.destroy_node()
    if args.timeout is not None and not received.is_set():  # (with or without --once)
        raise LaunchError(f"no message on {topic} within {args.timeout:g} s")
    return 0


def echo_options(args: argparse.Namespace) -> Any:
    """message → printable data, as `--no-arr`, `--no-str` and the truncation say."""
    from launcher.bus.messages import echo_data

    limit = None if args.full_length else args.truncate_length
    return lambda message, type_name: echo_data(message, type_name, limit=limit,
                                                no_arr=args.no_arr, no_str=args.no_str)


def _filter(expression: str | None) -> Any:
    """`--filter EXPR` as a test of a message; the expression is checked before anything
    starts, and a message it fails on is said once and not printed."""
    from launcher.bus.messages import to_data
    from launcher.description.safe_expression import (
        ExpressionError,
        check_expression,
        evaluate,
        fields_of,
    )

    if expression is None:
        return None
    try:
        check_expression(expression, ("m",))
    except ExpressionError as exc:
        raise UsageError(f"--filter: {exc}") from None
    failed: list[str] = []

    def accept(message: Any) -> bool:
        try:
            return bool(evaluate(expression, {"m": fields_of(to_data(message))}))
        except ExpressionError as exc:
            if not failed:
                failed.append(str(exc))
                print(f"--filter: {exc}; such messages are not printed", file=sys.stderr)
            return False

    return accept
