"""`launcher param load`: set a node's parameters from a params file."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.bus import parameters as params
from launcher.cli.param import client
from launcher.errors import LaunchError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    client.add_node_argument(parser)
    parser.add_argument("file", help="a params YAML file (its /NODE or /** section)")
    client.add_timeout_option(parser)


def run(args: argparse.Namespace) -> int:
    """As `ros2 param load NODE FILE`: the file's section for the node (its full name, or
    `/**`) set parameter by parameter; each result said."""
    import yaml

    from launcher.user_files import read_text

    try:
        document = yaml.safe_load(read_text(args.file)) or {}
    except OSError as exc:
        raise LaunchError(f"cannot read '{args.file}': {exc.strerror}") from None
    except yaml.YAMLError as exc:
        raise LaunchError(f"{args.file}: not valid YAML: {exc}") from None
    sections = [section.get("ros__parameters", {}) for key, section in document.items()
                if key in (args.node, args.node.lstrip("/"), "/**")
                and isinstance(section, dict)] if isinstance(document, dict) else []
    if not sections:
        raise LaunchError(f"{args.file} has no parameters for {args.node} (expected a "
                          f"'{args.node}:' or '/**:' section with 'ros__parameters:')")
    flat: dict[str, Any] = {}
    for section in sections:
        flat.update(_flatten(section))
    messages = [client.parameter_message(n, v) for n, v in flat.items()]
    response = client.call_parameters(args, params.SET, "set_parameters",
                                      {"parameters": messages})
    for name, result in zip(flat, response.results, strict=True):
        print(f"Set parameter {name} successful" if result.successful else
              f"Set parameter {name} failed: {result.reason}")
    return 0


def _flatten(tree: dict[str, Any], outer: str = "") -> dict[str, Any]:
    flat: dict[str, Any] = {}
    for key, value in tree.items():
        if isinstance(value, dict):
            flat.update(_flatten(value, f"{outer}{key}."))
        else:
            flat[f"{outer}{key}"] = value
    return flat
