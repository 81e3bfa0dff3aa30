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
from launcher.errors import ExecutionError
from launcher.private import write_private
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


def graph_name(context: LaunchContext, name: str) -> str:
    """A parameter's full ROS 1 name: in the current namespace unless it starts with /; a
    nested (dotted) name is a path."""
    if name.startswith("/"):
        return "/" + "/".join(p for p in name.replace(".", "/").split("/") if p)
    return params.join_namespace(params.namespace(context), name.replace(".", "/")) or "/"


def to_graph(context: LaunchContext, name: str, value: Any) -> None:
    """A ROS 1 parameter (its full name) for the graph's parameter server; one that ROS 1's
    master (XML-RPC) cannot hold is refused, as roslaunch fails to set it."""
    _check_xmlrpc(name, value)
    params.add_graph_parameter(context, name, value, loader, params_folder(context))


XMLRPC_INT = 2**31 - 1  # XML-RPC's int is 32 bits


def _check_xmlrpc(name: str, value: Any) -> None:
    if value is None:
        raise ExecutionError(f"parameter [{name}] is null: ROS 1's parameter server "
                             "(XML-RPC) holds no null; give it a value, or leave it out")
    if isinstance(value, int) and not isinstance(value, bool) and \
            not -XMLRPC_INT - 1 <= value <= XMLRPC_INT:
        raise ExecutionError(f"parameter [{name}]: {value} does not fit ROS 1's int (XML-RPC's "
                             f"32 bits: {-XMLRPC_INT - 1} to {XMLRPC_INT}); give type=\"double\""
                             " or type=\"str\"")
    for item in value.values() if isinstance(value, dict) else \
            value if isinstance(value, list | tuple) else ():
        _check_xmlrpc(name, item)


def loader(path: Path) -> Action:
    """The action that puts a launch's ROS 1 parameters on the server from `path`."""
    return LoadGraphParameters(file=path)


@dataclass(kw_only=True, eq=False)
class LoadGraphParameters(Action):
    """Puts the ROS 1 parameters gathered so far (queued by the first of them) on the graph's
    parameter server, after the launch's `rosparam delete|dump` have run, through a helper
    process (launcher/nodes/load_parameters.py) that stays on the graph while the launch runs.
    The nodes start once it is done (LaunchService.hold_graph); if it fails, none do."""

    file: Path

    def execute(self, context: LaunchContext) -> Any:
        import json  # only for a ROS 1 launch's parameters

        values, context.graph_parameters = context.graph_parameters, {}
        commands, context.graph_commands = context.graph_commands, []
        context.graph_parameters_file = None  # any later ones: a file and a process of their own
        if context.service is None:
            return None
        write_private(self.file, json.dumps({"before": commands, "set": values}))
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

    def machine_of(self, context: LaunchContext) -> None:
        return None  # (the launch's own: here, whatever machine its scope names)
