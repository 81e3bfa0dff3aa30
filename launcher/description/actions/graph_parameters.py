"""ROS 1's parameter server, fed by a launch: each parameter's full graph name, and the helper
that puts what a roslaunch file sets onto the graph's parameter server."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

from launcher.description import parameters as params
from launcher.description.action import Action
from launcher.description.actions.executable import ExecuteProcess
from launcher.description.actions.param_entry import params_folder
from launcher.private import write_private
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


def graph_name(context: LaunchContext, name: str) -> str:
    """A parameter's full ROS 1 name: in the current namespace unless it starts with /; a
    nested (dotted) name is a path."""
    if name.startswith("/"):
        return "/" + "/".join(p for p in name.split("/") if p)
    return params.join_namespace(params.namespace(context), name.replace(".", "/")) or "/"


def to_graph(context: LaunchContext, name: str, value: Any) -> None:
    """A ROS 1 parameter (its full name) for the graph's parameter server."""
    params.add_graph_parameter(context, name, value, loader, params_folder(context))


def loader(path: Path) -> Action:
    """The action that puts a launch's ROS 1 parameters on the server from `path`."""
    return LoadGraphParameters(file=path)


@dataclass(kw_only=True, eq=False)
class LoadGraphParameters(Action):
    """Puts the ROS 1 parameters gathered so far (queued by the first of them) on the graph's
    parameter server, after the server forgets what the launch deleted, through a helper
    process (launcher/nodes/load_parameters.py) that writes FILE.loaded when done (the nodes
    started meanwhile wait for that before they ask the server: lineage.GRAPH_PARAMETERS) and
    stays on the graph while the launch runs."""

    file: Path

    def execute(self, context: LaunchContext) -> Any:
        import json  # only for a ROS 1 launch's parameters

        values, context.graph_parameters = context.graph_parameters, {}
        deletions, context.graph_deletions = context.graph_deletions, []
        context.graph_parameters_file = None  # any later ones: a file and a process of their own
        if context.service is None:
            return None
        write_private(self.file, json.dumps({"delete": deletions, "set": values}))
        return [_Helper(cmd=[sys.executable, "-m", "launcher.nodes.load_parameters",
                             str(self.file)], name="load_parameters", output="screen",
                        where=self.where)]


DONE_LINE = "set on the graph's parameter server"  # load_parameters says so once they are


@dataclass(kw_only=True, eq=False)
class _Helper(ExecuteProcess):
    """A process that holds the graph (and so the parameters) while the launch runs, and
    does not keep the launch running."""

    def spec(self, context: LaunchContext) -> Any:
        spec = super().spec(context)
        spec.helper_done_line = DONE_LINE
        return spec
