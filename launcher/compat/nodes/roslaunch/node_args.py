"""roslaunch.node_args: a node's command line and the nodes of a launch, as `roslaunch
--args`, `--nodes` and `--find-node` print them (launcher's roslaunch views, over a dry run of
the files)."""

from __future__ import annotations

import os
import shlex
from typing import Any

from launcher.errors import LaunchError
from roslaunch.config import load_config_default  # noqa: F401 (roslaunch.node_args has it)
from roslaunch.core import RLException, local_machine, setup_env


class NodeParamsException(Exception):
    """A node that is not in the launch, or whose command line cannot be made."""


def loaded(roslaunch_files: list[str], arguments: dict[str, str] | None = None) -> Any:
    """The files loaded by a dry run (launcher's roslaunch views)."""
    from pathlib import Path

    from launcher.cli.ros1.roslaunch import combined
    from launcher.cli.ros1.roslaunch_views import Loaded
    from launcher.cli.workspace import load_index

    try:
        return Loaded(combined([Path(f) for f in roslaunch_files]), arguments or {},
                      load_index())
    except LaunchError as exc:
        raise RLException(str(exc)) from None


def get_node_list(config: Any) -> list[str]:
    """The full names of the config's nodes and tests."""
    return [f"{n.namespace}{n.name}" for n in config.nodes + config.tests if n.name]


def print_node_list(roslaunch_files: list[str]) -> None:
    """Print the full name of each node of the files."""
    print("\n".join(loaded(roslaunch_files).nodes))


def print_node_filename(node_name: str, roslaunch_files: list[str]) -> None:
    """Print the launch file that declares node `node_name`."""
    found = loaded(roslaunch_files)
    try:
        print(found.where[found.node(node_name)].file)
    except LaunchError as exc:
        raise RLException(str(exc)) from None


def get_node_args(node_name: str, roslaunch_files: list[str]) -> list[str]:
    """Node `node_name`'s command line: the variables the launch sets for it (VAR=value
    words), then its argv."""
    found = loaded(roslaunch_files)
    try:
        spec = found.nodes[found.node(node_name)]
    except LaunchError as exc:
        raise NodeParamsException(str(exc)) from None
    changed = [f"{k}={shlex.quote(v)}" for k, v in sorted(spec.env.items())
               if not k.startswith("LAUNCHER_") and found.environment.get(k) != v]
    return [*changed, *spec.argv]


def print_node_args(node_name: str, roslaunch_files: list[str]) -> None:
    """Print node `node_name`'s command line, as `roslaunch --args` does."""
    print(" ".join(shlex.quote(w) if "=" not in w else w
                   for w in get_node_args(node_name, roslaunch_files)))


def create_local_process_args(node: Any, machine: Any, env: dict[str, str] | None = None
                              ) -> list[str]:
    """The command line of `node` on this host: its launch prefix, its executable (found in
    its package as launcher finds one), its args and remaps, __name:= and __log:=."""
    from launcher.packages.index import PackageIndex

    if not node.type:
        raise NodeParamsException("Node type is not set")
    environment = setup_env(node, machine or local_machine(), "", env)
    package = PackageIndex.from_environment(environment).get(node.package)
    matches = sorted(p for p in package.path.rglob(node.type)
                     if p.is_file() and os.access(p, os.X_OK))
    if not matches:
        raise NodeParamsException(f"Cannot locate node of type [{node.type}] in package "
                                  f"[{node.package}]")
    words = [*shlex.split(node.launch_prefix or ""), str(matches[0]),
             *shlex.split(node.args or ""), *(f"{a}:={b}" for a, b in node.remap_args)]
    if node.name:
        words.append(f"__name:={node.name}")
    return words
