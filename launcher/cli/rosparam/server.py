"""The graph's parameter server, as rosparam reaches it: names resolved as ROS 1 resolves
them, a client node for the call, values read from and written as YAML."""

from __future__ import annotations

import argparse
import os
from typing import Any

from launcher.errors import LaunchError, UsageError


class NoServer(LaunchError):
    pass


def resolve(name: str) -> str:
    """A ROS 1 name made global, as rosparam's script_resolve_name does."""
    if name.startswith("/"):
        return name
    if name.startswith("~"):
        raise UsageError(f"'{name}': a private name (~) has no meaning here; give the node's "
                         "full name, as /NODE/PARAM")
    space = os.environ.get("ROS_NAMESPACE", "/").strip("/")
    return f"/{space}/{name}" if space else f"/{name}"


def with_server(args: argparse.Namespace, work: Any) -> Any:
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


def yaml_text(value: Any) -> str:
    from launcher.bus.graph_parameters import dump_text

    return dump_text(value)


def read_file(path: str) -> str:
    from launcher.user_files import read_text

    try:
        return read_text(path)
    except OSError as exc:
        raise LaunchError(f"cannot read '{path}': {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise LaunchError(f"'{path}' is not UTF-8 text") from None
