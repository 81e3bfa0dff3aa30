"""Run-wide ROS settings for the nodes after them (scoped by `group`, as in ROS 2):
`push_ros_namespace`, `set_parameter`, `set_parameters_from_file`, `set_remap`,
`set_use_sim_time`."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launcher.description import parameters as params
from launcher.description.action import Action
from launcher.description.actions.graph_parameters import graph_name, loader, to_graph
from launcher.description.actions.param_entry import params_folder, rosparam_entry
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.substitution import perform_text
from launcher.errors import ExecutionError
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext


@action("push_ros_namespace", "push-ros-namespace")
@dataclass(kw_only=True, eq=False)
class PushRosNamespace(Action):
    namespace: Any = attr(Kind.TEXT, aliases=("ns",), required=True,
                          doc="Namespace for the nodes after it (relative ones nest).")

    def execute(self, context: LaunchContext) -> None:
        params.push_namespace(context, perform_text(context, self.namespace))


@action("set_parameter")
@dataclass(kw_only=True, eq=False)
class SetParameter(Action):
    name: Any = attr(Kind.TEXT, doc="Parameter name.")
    value: Any = attr(Kind.VALUE, doc="Its value, for every later node.")
    type: Any = attr(Kind.TEXT, choices=params.TYPES,
                     doc="As a node's param: default as launch_ros types the value.")
    command: Any = attr(Kind.TEXT, doc="roslaunch's: the value is this command's output.")
    textfile: Any = attr(Kind.TEXT, doc="roslaunch's: the value is this file's text.")
    rosparam_file: Any = attr(Kind.TEXT, doc="roslaunch's rosparam: a YAML map of parameters.")
    rosparam: Any = attr(Kind.TEXT, doc="roslaunch's rosparam: the YAML, inline.")
    allow_substs: Any = attr(Kind.BOOL, doc="rosparam's subst_value.")
    rosparam_command: Any = attr(Kind.TEXT, choices=("load", "dump", "delete"),
                                 doc="roslaunch's rosparam command (default load).")
    server: Any = attr(Kind.BOOL, False, doc="roslaunch's: also on the graph's parameter "
                                             "server, by its full name.")
    server_only: Any = attr(Kind.BOOL, False, doc="roslaunch's own (/run_id, /rosdistro): on "
                                                  "the graph's parameter server alone, not "
                                                  "for the nodes.")
    private: Any = attr(Kind.BOOL, False, doc="roslaunch's ~name outside a node: each later "
                                              "node's own parameter (on the server under "
                                              "the node's name).")

    def __post_init__(self) -> None:
        super().__post_init__()
        if self.value is None:
            self.value = params.ros1_value(self.command, self.textfile)
        if self.rosparam_command is None and self.rosparam_file is None and \
                self.rosparam is None and (self.name is None or self.value is None):
            raise ExecutionError("set_parameter needs 'name' and 'value'")
        if self.value is not None and not isinstance(self.value, params.Written | list):
            self.value = [params.python_value(v) for v in self.value] \
                if isinstance(self.value, list | tuple) else params.python_value(self.value)

    def execute(self, context: LaunchContext) -> None:
        command = resolve(context, self.rosparam_command, Kind.TEXT, "command") \
            if self.rosparam_command is not None else "load"
        if command != "load":
            self._dump_or_delete(context, command)
            return
        server = resolve(context, self.server, Kind.BOOL, "server")
        if self.rosparam_file is not None or self.rosparam is not None:
            # (under a global ns=, the names are global, whatever the namespace)
            root = "/" if self.name is not None and \
                perform_text(context, self.name).startswith("/") else ""
            alone = resolve(context, self.server_only, Kind.BOOL, "server_only")
            for name, value in rosparam_entry(context, self, "", self.where).items():
                if alone:
                    to_graph(context, graph_name(context, root + name), value)
                else:
                    self._set(context, root + name, value, server)
            return
        name = perform_text(context, self.name)
        kind = resolve(context, self.type, Kind.TEXT, "type") if self.type else None
        try:
            value = params.value_of(context, self.value, kind, name)
        except ExecutionError as exc:
            raise exc if exc.location else exc.at(self.where) from None
        alone = resolve(context, self.server_only, Kind.BOOL, "server_only")
        private = resolve(context, self.private, Kind.BOOL, "private")
        for leaf, item in params.unrolled(name, value).items():  # (roslaunch's yaml maps)
            if alone:
                to_graph(context, graph_name(context, leaf), item)
            elif private:
                params.add_private_parameter(context, leaf, item)
            else:
                self._set(context, leaf, item, server)

    @staticmethod
    def _set(context: LaunchContext, name: str, value: Any, server: bool) -> None:
        if server:  # a name with a leading / is the graph's, whatever the namespace
            to_graph(context, graph_name(context, name), value)
            name = name.lstrip("/")
        params.add_global_parameter(context, name, value)

    def _dump_or_delete(self, context: LaunchContext, command: str) -> None:
        """roslaunch's `<rosparam command="dump|delete">` (and clear_params): run on the
        server before the launch's parameters are set (params.graph_command)."""
        name = graph_name(context, perform_text(context, self.name)
                          if self.name is not None else "/")
        if command == "delete":
            params.graph_command(context, ["delete", name], loader, params_folder(context))
            return
        if self.rosparam_file is None:
            raise ExecutionError("<rosparam command=\"dump\"> needs file=", self.where)
        path = Path(perform_text(context, self.rosparam_file)).absolute()
        params.graph_command(context, ["dump", name, str(path)], loader,
                             params_folder(context))


@action("set_parameters_from_file")
@dataclass(kw_only=True, eq=False)
class SetParametersFromFile(Action):
    filename: Any = attr(Kind.TEXT, required=True, doc="A params YAML file for later nodes.")

    def execute(self, context: LaunchContext) -> None:
        path = Path(perform_text(context, self.filename))
        params.check_params_file(path, self.where)
        params.add_global_parameter_file(context, str(path))


@action("set_remap")
@dataclass(kw_only=True, eq=False)
class SetRemap(Action):
    source: Any = attr(Kind.TEXT, name="from", required=True, doc="Name to remap.")
    target: Any = attr(Kind.TEXT, name="to", required=True, doc="What it becomes.")

    def execute(self, context: LaunchContext) -> None:
        params.add_remap(context, perform_text(context, self.source),
                         perform_text(context, self.target))


@action("set_use_sim_time")
@dataclass(kw_only=True, eq=False)
class SetUseSimTime(Action):
    value: Any = attr(Kind.BOOL, required=True, doc="true: nodes follow /clock.")

    def execute(self, context: LaunchContext) -> None:
        # `-p use_sim_time:=true` on every later node, as launch_ros's Python action does
        params.add_global_parameter(context, "use_sim_time",
                                    resolve(context, self.value, Kind.BOOL, "value"))
