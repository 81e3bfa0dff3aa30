"""`launcher rosparam list | get | set | delete | dump | load`: ROS 1's `rosparam` over the
graph's parameter server (bus/graph_parameters.py), which the graph's router hosts and a
ROS 1 launch fills. Names are ROS 1's (`/robot1/robot_description`); a relative one is in
ROS_NAMESPACE (default /)."""

from __future__ import annotations

import argparse
import os
import sys
from typing import Any

from launcher.cli import positive_number
from launcher.errors import LaunchError, UsageError


class NoServer(LaunchError):
    pass


def add_parser(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser("rosparam", help="ROS 1's rosparam: the graph's parameter server "
                                             "(list, get, set, delete, dump, load)")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True)
    listing = verbs.add_parser("list", help="the parameter names (below a namespace)")
    listing.add_argument("namespace", nargs="?", default="/", help="list below this name")
    listing.set_defaults(run=run_list)
    get = verbs.add_parser("get", help="a parameter's value, or a namespace's as YAML")
    get.add_argument("-p", dest="pretty", action="store_true",
                     help="pretty print (a namespace as indented keys, text as it is)")
    get.add_argument("name", help="the parameter (or a namespace: all below it)")
    get.set_defaults(run=run_get)
    put = verbs.add_parser("set", help="set a parameter (the value is read as YAML)")
    put.add_argument("-t", "--textfile", metavar="FILE",
                     help="the value is this file's text")
    put.add_argument("name", help="the parameter")
    put.add_argument("value", nargs="?", help="its value, read as YAML (or -t FILE)")
    put.set_defaults(run=run_set)
    delete = verbs.add_parser("delete", help="delete a parameter and everything below it")
    delete.add_argument("name", help="the parameter, with all below it")
    delete.set_defaults(run=run_delete)
    dump = verbs.add_parser("dump", help="a namespace as YAML, to a file (or stdout)")
    dump.add_argument("file", nargs="?", help="where to write it (default: stdout)")
    dump.add_argument("namespace", nargs="?", default="/", help="dump below this name")
    dump.set_defaults(run=run_dump)
    load = verbs.add_parser("load", help="set the parameters of a YAML file (into a "
                                         "namespace)")
    load.add_argument("file", help="a YAML file ('-': stdin)")
    load.add_argument("namespace", nargs="?", default="/", help="load below this name")
    load.set_defaults(run=run_load)
    for sub in (listing, get, put, delete, dump, load):
        sub.add_argument("--timeout", type=positive_number, default=5.0, metavar="SECONDS",
                         help="how long to wait for the server's answer (default 5 s)")


def resolve(name: str) -> str:
    """A ROS 1 name made global, as rosparam's script_resolve_name does."""
    if name.startswith("/"):
        return name
    if name.startswith("~"):
        raise UsageError(f"'{name}': a private name (~) has no meaning here; give the node's "
                         "full name, as /NODE/PARAM")
    space = os.environ.get("ROS_NAMESPACE", "/").strip("/")
    return f"/{space}/{name}" if space else f"/{name}"


def _with_server(args: argparse.Namespace, work: Any) -> Any:
    from launcher.bus import graph_parameters as graph
    from launcher.bus.node import Node

    node = Node("_launcher_rosparam", argv=[], parameter_services=False)
    try:
        server = graph.GraphParameters(node, args.timeout)
        if not server.available(args.timeout):
            raise NoServer(f"the graph's parameter server ({graph.NODE}, which the graph's "
                           f"router hosts) did not answer within {args.timeout:g} s; is the "
                           "router of LAUNCHER_ROUTER an older launcher's?")
        return work(server)
    finally:
        node.destroy_node()


def _yaml(value: Any) -> str:
    from launcher.bus.graph_parameters import dump_text

    return dump_text(value)


def run_list(args: argparse.Namespace) -> int:
    for name in _with_server(args, lambda s: s.names(resolve(args.namespace))):
        print(name)
    return 0


def run_get(args: argparse.Namespace) -> int:
    value = _with_server(args, lambda s: s.get(resolve(args.name)))
    if args.pretty and isinstance(value, dict):
        _pretty(value, "")
    elif args.pretty and isinstance(value, str):
        print(value)
    else:
        print(_yaml(value))
    return 0


def _pretty(value: dict[str, Any], indent: str) -> None:
    """rosparam get -p: keys sorted, dicts indented, text as it is."""
    for key in sorted(value):
        item = value[key]
        if isinstance(item, dict):
            print(f"{indent}{key}:")
            _pretty(item, indent + "  ")
        elif isinstance(item, str) and "\n" in item:
            print(f"{indent}{key}: |")
            for line in item.split("\n"):
                print(f"{indent}  {line}")
        else:
            print(f"{indent}{key}: {item if isinstance(item, str) else _yaml(item)}")


def run_set(args: argparse.Namespace) -> int:
    if args.textfile is not None:
        if args.value is not None:
            raise UsageError("give either a value or --textfile, not both")
        value: Any = _read(args.textfile)
    elif args.value is None:
        raise UsageError("rosparam set needs a value (or --textfile FILE)")
    else:
        value = _parse(args.value, "the value")
    _with_server(args, lambda s: s.set(resolve(args.name), value))
    return 0


def _parse(text: str, where: str) -> Any:
    """YAML, as rosparam reads a value; an empty one is the empty string."""
    import yaml

    if text == "":
        return ""
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        at = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        raise UsageError(f"{where} is not valid YAML{at}: "
                         f"{getattr(exc, 'problem', None) or exc}") from None


def _read(path: str) -> str:
    from launcher.user_files import read_text

    try:
        return read_text(path)
    except OSError as exc:
        raise LaunchError(f"cannot read '{path}': {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise LaunchError(f"'{path}' is not UTF-8 text") from None


def run_delete(args: argparse.Namespace) -> int:
    _with_server(args, lambda s: s.delete(resolve(args.name)))
    return 0


def run_dump(args: argparse.Namespace) -> int:
    text = _yaml(_with_server(args, lambda s: s.get(resolve(args.namespace)))) + "\n"
    if args.file in (None, "-"):
        sys.stdout.write(text)
        return 0
    try:
        with open(args.file, "w", encoding="utf-8") as handle:
            handle.write(text)
    except OSError as exc:
        raise LaunchError(f"cannot write '{args.file}': {exc.strerror}") from None
    return 0


def run_load(args: argparse.Namespace) -> int:
    import yaml

    from launcher.errors import Location

    text = sys.stdin.read() if args.file == "-" else _read(args.file)
    try:
        document = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = Location(args.file, mark.line + 1, mark.column + 1) if mark else None
        raise LaunchError(f"not valid YAML: {getattr(exc, 'problem', None) or exc}",
                          where) from None
    space = resolve(args.namespace)
    if isinstance(document, dict):
        values = {f"{space.rstrip('/')}/{key}": value for key, value in document.items()}
        _with_server(args, lambda s: s.set_many(values))
    elif document is not None:
        if space == "/":
            raise LaunchError(f"'{args.file}' holds one value, not a map of names; give the "
                              "namespace (its name) to load it into")
        _with_server(args, lambda s: s.set(space, document))
    return 0
