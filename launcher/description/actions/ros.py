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
            for name, value in rosparam_entry(context, self, "", self.where).items():
                self._set(context, name, value, server)
            return
        name = perform_text(context, self.name)
        kind = resolve(context, self.type, Kind.TEXT, "type") if self.type else None
        try:
            value = params.value_of(context, self.value, kind, name)
        except ExecutionError as exc:
            raise exc if exc.location else exc.at(self.where) from None
        if resolve(context, self.server_only, Kind.BOOL, "server_only"):
            to_graph(context, graph_name(context, name), value)
            return
        if resolve(context, self.private, Kind.BOOL, "private"):
            params.add_private_parameter(context, name, value)
            return
        self._set(context, name, value, server)

    @staticmethod
    def _set(context: LaunchContext, name: str, value: Any, server: bool) -> None:
        if server:  # a name with a leading / is the graph's, whatever the namespace
            to_graph(context, graph_name(context, name), value)
            name = name.lstrip("/")
        params.add_global_parameter(context, name, value)

    def _dump_or_delete(self, context: LaunchContext, command: str) -> None:
        """roslaunch's `<rosparam command="dump|delete">`, over what this launch has set."""
        prefix = perform_text(context, self.name).strip("/").replace("/", ".") \
            if self.name is not None else ""

        def under(name: str) -> bool:
            return not prefix or name == prefix or name.startswith(prefix + ".")

        if command == "delete":
            if resolve(context, self.server, Kind.BOOL, "server"):
                params.delete_graph_parameters(
                    context, graph_name(context, perform_text(context, self.name)
                                        if self.name is not None else "/"),
                    loader, params_folder(context))
            if resolve(context, self.server_only, Kind.BOOL, "server_only"):
                return  # (clear_params: what the server held, not what this launch sets)
            kept = tuple(item for item in params.global_settings(context)
                         if item[0] == params.FILE or not under(item[0]))
            context.configurations[params.GLOBAL_PARAMETERS] = kept  # type: ignore[assignment]
            return
        if self.rosparam_file is None:
            raise ExecutionError("<rosparam command=\"dump\"> needs file=", self.where)
        found = {n: v for n, v in params.global_parameters(context).items() if under(n)}
        document: Any = {}
        if list(found) == [prefix]:  # one parameter: its value, as rosparam dump writes it
            document = found[prefix]
        for name, value in found.items() if list(found) != [prefix] else ():
            *outer, last = (name[len(prefix) + 1:] if prefix else name).split(".")
            level = document
            for part in outer:
                level = level.setdefault(part, {})
            level[last] = value
        path = Path(perform_text(context, self.rosparam_file))
        import yaml

        try:
            path.write_text(yaml.safe_dump(document, sort_keys=False, allow_unicode=True))
        except OSError as exc:
            raise ExecutionError(f"<rosparam command=\"dump\">: cannot write '{path}': "
                                 f"{exc.strerror}", self.where) from None


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
