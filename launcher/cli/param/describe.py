"""`launcher param describe`: parameters' types, descriptions and constraints."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.bus import parameters as params
from launcher.cli import completion, positive_number
from launcher.cli.param.client import call_parameters


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    parser.add_argument("names", nargs="+", metavar="name", help="the parameters")
    parser.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                        help="how long to wait for the node's answer (default 5 s)")


def run(args: argparse.Namespace) -> int:
    """As `ros2 param describe NODE NAME…`."""
    response = call_parameters(args, params.DESCRIBE, "describe_parameters", {"names": args.names})
    for descriptor in response.descriptors:
        print(describe_lines(descriptor))
    return 0


def describe_lines(descriptor: Any) -> str:
    lines = [f"Parameter name: {descriptor.name}",
             f"  Type: {params.TYPE_NAMES.get(descriptor.type, 'unknown')}"]
    if descriptor.description:
        lines.append(f"  Description: {descriptor.description}")
    constraints = []
    if descriptor.read_only:
        constraints.append("    Read only: true")
    for span in list(descriptor.floating_point_range) + list(descriptor.integer_range):
        constraints += [f"    Min value: {span.from_value}", f"    Max value: {span.to_value}"]
        if span.step:
            constraints.append(f"    Step: {span.step}")
    if descriptor.additional_constraints:
        constraints.append(f"    {descriptor.additional_constraints}")
    if constraints:
        lines += ["  Constraints:", *constraints]
    return "\n".join(lines)
