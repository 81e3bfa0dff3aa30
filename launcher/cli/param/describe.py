"""`launcher param describe`: parameters' types, descriptions and constraints."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.bus import parameters as params
from launcher.cli.param import client


def add_arguments(parser: argparse.ArgumentParser) -> None:
    client.add_names_arguments(parser)


def run(args: argparse.Namespace) -> int:
    """As `ros2 param describe NODE NAME…`."""
    response = client.call_parameters(args, params.DESCRIBE, "describe_parameters",
                                      {"names": args.names})
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
