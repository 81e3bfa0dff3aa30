"""`launcher param list | get | set | dump | load NODE …`, through the node's parameter
services, as `ros2 param` has them."""

from __future__ import annotations

import argparse
from typing import Any

from launcher.bus import parameters as params
from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.bus.ros_args import typed
from launcher.cli import completion, positive_number
from launcher.errors import LaunchError


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("param", help="parameters of a running node: list, get, set, "
                                          "describe, delete, dump, load")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="a node's parameter names")
    listing.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    listing.set_defaults(run=run_list)
    get = verbs.add_parser("get", help="one parameter's value")
    get.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    get.add_argument("name", help="the parameter")
    get.set_defaults(run=run_get)
    put = verbs.add_parser("set", help="set one parameter (the value is read as YAML)")
    put.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    put.add_argument("name", help="the parameter")
    put.add_argument("value", help="its new value, read as YAML")
    put.set_defaults(run=run_set)
    describe = verbs.add_parser("describe", help="parameters' types, descriptions and "
                                                 "constraints")
    describe.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    describe.add_argument("names", nargs="+", metavar="name", help="the parameters")
    describe.set_defaults(run=run_describe)
    delete = verbs.add_parser("delete", help="delete parameters (a node refuses it for one "
                                             "declared with a fixed type)")
    delete.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    delete.add_argument("names", nargs="+", metavar="name", help="the parameters")
    delete.set_defaults(run=run_delete)
    dump = verbs.add_parser("dump", help="all of a node's parameters, as a params file")
    dump.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    dump.set_defaults(run=run_dump)
    load = verbs.add_parser("load", help="set a node's parameters from a params file")
    load.add_argument("node", help="the node's full name").completer = completion.nodes  # type: ignore[attr-defined]
    load.add_argument("file", help="a params YAML file (its /NODE or /** section)")
    load.set_defaults(run=run_load)
    for sub in (listing, get, put, describe, delete, dump, load):
        sub.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                         help="how long to wait for the node's answer (default 5 s)")


def _call(args: argparse.Namespace, service: str, suffix: str, request: dict) -> object:
    node = Node("_launcher_param", argv=[], parameter_services=False)
    try:
        client = node.create_client(service, f"{args.node.rstrip('/')}/{suffix}")
        request_type, _ = client.request_type, client.response_type
        return client.call(build(request_type, request), args.timeout)
    finally:
        node.destroy_node()


def run_list(args: argparse.Namespace) -> int:
    response = _call(args, params.LIST, "list_parameters", {})
    print(f"{args.node}:")
    for name in response.result.names:
        print(f"  {name}")
    return 0


def run_get(args: argparse.Namespace) -> int:
    response = _call(args, params.GET, "get_parameters", {"names": [args.name]})
    print(params.describe(params.from_message(response.values[0])))
    return 0


def _parameter(name: str, value: Any) -> dict:
    message = params.to_message(value)
    return {"name": name, "value": {f: getattr(message, f) for f in message.__dataclass_fields__
                                    if f != "__msgtype__"}}


def run_set(args: argparse.Namespace) -> int:
    response = _call(args, params.SET, "set_parameters",
                     {"parameters": [_parameter(args.name, typed(args.value))]})
    if response.results[0].successful:
        print("Set parameter successful")
        return 0
    print(f"Setting parameter failed: {response.results[0].reason}")
    return 1


def run_describe(args: argparse.Namespace) -> int:
    """As `ros2 param describe NODE NAME…`."""
    response = _call(args, params.DESCRIBE, "describe_parameters", {"names": args.names})
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


def run_delete(args: argparse.Namespace) -> int:
    """As `ros2 param delete NODE NAME…`: each result said; exit 1 if one was refused."""
    response = _call(args, params.SET, "set_parameters",
                     {"parameters": [{"name": n, "value": {"type": params.NOT_SET}}
                                     for n in args.names]})
    failed = 0
    for result in response.results:
        if result.successful:
            print("Deleted parameter successfully")
        else:
            failed += 1
            print(f"Deleting parameter failed: {result.reason}")
    return 1 if failed else 0


def run_dump(args: argparse.Namespace) -> int:
    """As `ros2 param dump NODE`: `/NODE: {ros__parameters: {…}}` on stdout, dotted names
    nested."""
    import yaml

    names = list(_call(args, params.LIST, "list_parameters", {}).result.names)
    values = _call(args, params.GET, "get_parameters", {"names": names}).values
    tree = params.nested((name, params.from_message(value))
                         for name, value in zip(names, values, strict=True))
    print(yaml.safe_dump({args.node: {"ros__parameters": tree}}, sort_keys=True), end="")
    return 0


def run_load(args: argparse.Namespace) -> int:
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
    response = _call(args, params.SET, "set_parameters",
                     {"parameters": [_parameter(n, v) for n, v in flat.items()]})
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
