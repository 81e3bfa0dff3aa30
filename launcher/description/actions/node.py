"""`node`: run a package's executable as a ROS node (launch_ros's Node).

The command line follows ROS 2's layout:
    EXE ARGS… --ros-args ROS_ARGS… -r __node:=NAME -r __ns:=NS
        --params-file FILE… -r from:=to…
Parameters given inline (and global ones from set_parameter) go into a params file that
launcher writes under the run's log folder; `from` files are passed as they are.

ROS's GUI tools (rviz2, rqt, …) are not part of launcher: when their package is not installed,
such a node is one error and the rest of the launch runs (ROS 2 would end the whole launch).
"""

from __future__ import annotations

import os
from operator import attrgetter
from pathlib import Path
from typing import Any

from launcher.description import parameters as params
from launcher.description.actions.executable import ExecuteProcess, check_runnable
from launcher.description.actions.graph_parameters import to_graph
from launcher.description.actions.machine import Placement, lookup, params_files
from launcher.description.actions.param_entry import (
    ParamEntry,
    parameter_groups,
    params_folder,
    python_parameters,
)
from launcher.description.condition import entry_applies, if_attr, unless_attr
from launcher.description.fields import Kind, attr, resolve
from launcher.description.registry import action
from launcher.description.ros_names import check_namespace, check_node_name
from launcher.description.substitution import Text_, perform_text, to_text
from launcher.errors import ExecutionError, LaunchError
from launcher.lineage import NODE_PARAMETERS
from launcher.packages.executables import Executable, find_executable
from launcher.packages.index import PackageNotFound
from launcher.records import dataclass
from launcher.runtime.context import LaunchContext
from launcher.runtime.machine import Machine, RemoteStart
from launcher.runtime.process import ProcessSpec

GUI_TOOLS = ("rqt", "rqt_gui", "rqt_graph", "rqt_plot", "rqt_console",
             "rqt_image_view", "rqt_robot_steering", "joint_state_publisher_gui", "gzclient")


def is_gui_tool(package: str) -> bool:
    """rqt and its plugins (rqt_topic, rqt_reconfigure, …), and the other GUI tools (rviz2
    and rviz are launcher's packages: the view is Foxglove's)."""
    return package in GUI_TOOLS or package.startswith("rqt_")


INSTEAD = ("the robot's data in Foxglove: `launcher run foxglove_bridge foxglove_bridge`; "
           "pictures of the world: `launcher sim snapshot -o world.png`; topics: "
           "`launcher topic echo`")


@dataclass(eq=False)
class RemapEntry:
    source: Text_ = attr(Kind.TEXT, name="from", required=True, doc="The name in the node.")
    target: Text_ = attr(Kind.TEXT, name="to", required=True, doc="The name it becomes.")
    only_if: Any = if_attr()
    only_unless: Any = unless_attr()


UNSPECIFIED_NAME = "<node_name_unspecified>"  # (launch_ros's words for what was not given)
UNSPECIFIED_SPACE = "<node_namespace_unspecified>"


@action("node")
@dataclass(kw_only=True, eq=False)
class Node(ExecuteProcess):
    cmd: Any = None  # made from package and executable
    package: Any = attr(Kind.TEXT, name="pkg", aliases=("package",),
                        doc="The package holding the executable (without it, the executable "
                            "is a command on PATH, as in launch_ros).")
    executable: Any = attr(Kind.TEXT, name="exec", aliases=("executable",), required=True,
                           doc="The executable's name in the package.")
    given_name: Any = attr(Kind.TEXT, name="name", doc="The node's name (-r __node:=).")
    namespace: Any = attr(Kind.TEXT, aliases=("ns",), doc="The node's namespace.")
    exec_name: Any = attr(Kind.TEXT, doc="Label for its output; default: the node name.")
    arguments: Any = attr(Kind.COMMAND, name="args", aliases=("arguments",),
                          doc="Arguments before --ros-args.")
    ros_arguments: Any = attr(Kind.COMMAND, name="ros_args", aliases=("ros_arguments",),
                              doc="Arguments after --ros-args.")
    parameters: list[Any] = attr(Kind.ENTRIES, name="param", entry=ParamEntry,
                                 doc="Parameters: name/value, nested, or from a file.")
    remappings: list[Any] = attr(Kind.ENTRIES, name="remap", entry=RemapEntry,
                                 doc="Topic and service remappings.")
    unique: Any = attr(Kind.BOOL, False, doc="roslaunch's rule: another node of the same "
                                             "full name is an error (else a warning).")
    server: Any = attr(Kind.BOOL, False, doc="roslaunch's: its own parameters also on the "
                                             "graph's parameter server (/NODE/NAME).")
    ros1: Any = attr(Kind.BOOL, False, doc="roslaunch's command line: ARGS, then FROM:=TO, "
                                           "__name:=, __ns:= and __log:=, the namespace also "
                                           "in ROS_NAMESPACE (no --ros-args).")
    home: Any = attr(Kind.TEXT, doc="roslaunch's cwd word: ROS_HOME (the default: the node "
                                    "runs in $ROS_HOME, else ~/.ros) or node (its "
                                    "executable's folder).")
    name: Any = None  # its process's label, once it has run (from exec_name / the name)

    def __post_init__(self) -> None:
        super().__post_init__()
        self.parameters = python_parameters(self.parameters)
        self.remappings = [r if isinstance(r, RemapEntry) else
                           RemapEntry(to_text(r[0]), to_text(r[1])) for r in self.remappings]

    def execute(self, context: LaunchContext) -> Any:
        try:
            return super().execute(context)
        except PackageNotFound as exc:
            package = perform_text(context, self.package)
            if not is_gui_tool(package) or context.service is None:
                raise
            context.service.report(ExecutionError(
                f"node of package '{package}' not started: {package} is a ROS GUI tool, not "
                f"part of launcher, and no ROS install provides it ({INSTEAD}); the rest of "
                "the launch runs", exc.location or self.where))
            return None

    def spec(self, context: LaunchContext):  # type: ignore[override]
        if context.packages is None:
            raise ExecutionError("node needs the package index, which this run lacks")
        ros1 = resolve(context, self.ros1, Kind.BOOL, "ros1")
        machine, later = self._machine(context, ros1)
        remote = later is not None or (machine is not None and not machine.local)
        found = self._executable(context, remote)
        node = self._node_name(context)
        space = self._namespace(context)
        if self.given_name is not None:
            check_node_name(node, self.where)
        check_namespace(space, self.where)
        own = [(perform_text(context, r.source), perform_text(context, r.target))
               for r in self.remappings if entry_applies(context, r)]
        words = self._parameter_arguments(context, node, space, node or found.name)
        if ros1:  # roslaunch's LoaderContext.remap_args: one per `from`, the latest, in order
            remaps: list[tuple[str, str]] = []
            for source, target in [*params.remaps(context), *own]:
                remaps = [r for r in remaps if r[0] != source] + [(source, target)]
        else:  # launch_ros's Node: its scope's (SetRemap), then its own; rcl takes the
            remaps = [*params.remaps(context), *own]  # first match, so the scope's win
        if ros1:  # roslaunch splits args= and launch-prefix= once substituted
            head = [*self.run_prefix(context), *self._ros1_words(context, self.prefix)]
            argv = [*head, *found.argv, *self._ros1_words(context, self.arguments)]
        else:
            head = self.launch_prefix(context)
            argv = [*head, *found.argv, *self._words(context, self.arguments)]
        if ros1:  # as roslaunch's node_args.create_local_process_args builds it
            argv += [f"{source}:={target}" for source, target in remaps]
            argv += [f"__name:={node}"] if node else []  # the namespace: ROS_NAMESPACE alone
        else:
            if self.ros_arguments is not None:  # launch_ros: these, then its own, each
                argv += ["--ros-args", *self._words(context, self.ros_arguments)]  # flagged
            argv += ["--ros-args"]
            argv += ["-r", f"__node:={node}"] if node else []
            # (a namespace given, even "", or pushed: launch_ros makes it absolute)
            if space or self.namespace is not None:
                argv += ["-r", f"__ns:={space or '/'}"]
            argv += words
            for source, target in remaps:
                argv += ["-r", f"{source}:={target}"]
        self._check_unique(context, node or found.name, space)
        self._expanded = (space or ("/" if self.namespace is not None else UNSPECIFIED_SPACE),
                          node or UNSPECIFIED_NAME)
        label = self.exec_name if self.exec_name is not None else self.given_name
        base = perform_text(context, label) if label is not None else found.name
        env = found.environment(self.environment(context))
        if ros1:
            own = {perform_text(context, e.name) for e in self.additional_env
                   if entry_applies(context, e)}
            if space and "ROS_NAMESPACE" not in own:  # nodeprocess.setup_env: the namespace
                env["ROS_NAMESPACE"] = space.rstrip("/") or "/"  # unslashed, under own env
            if words:  # its parameters, for launcher's own nodes (rospy reads the server)
                import json  # (ROS 1 alone: start-up time)

                env[NODE_PARAMETERS] = json.dumps(words)
        home = self._home(context) if ros1 else ""
        cwd = self._ros1_cwd(home, argv[0], env) if ros1 and not remote else None
        placement = Placement(machine, self._remote_start(context, len(head), argv, words)
                              if remote else None)
        spec = self.process_spec(context, argv, env, base, cwd, placement)
        if node:
            spec.node_name = f"{space.rstrip('/')}/{node}"
        if ros1:  # nodeprocess: the log file is named after the node's full name
            stem = "-".join(p for p in (*space.split("/"), spec.label) if p)
            import tempfile

            log = (context.log_dir or Path(tempfile.gettempdir())) / f"{stem}.log"
            spec.argv = [*spec.argv, f"__log:={log}"]
        self.name = spec.label  # (launch_ros's Node.name: its process's, once it has run)
        spec.joins_graph = True
        spec.after_loading = ros1  # roslaunch: once every file is read and its parameters set
        if later is not None:
            context.loaded_checks.append(lambda: self._place(context, spec, later, home))
        return spec

    # --- where it runs ----------------------------------------------------------------------
    def _machine(self, context: LaunchContext, ros1: bool) -> tuple[Machine | None, str | None]:
        """The machine it runs on; for a ROS 1 node naming one not declared yet, its name
        instead (roslaunch's assign_machines takes a machine declared anywhere in the
        launch: the node is placed once the launch files are read)."""
        if ros1 and self.machine is not None:
            name = perform_text(context, self.machine)
            if name not in context.machines:
                return None, name
        machine = self.machine_of(context)
        if machine is None and ros1:  # roslaunch's <machine default="true"> before it
            machine = context.default_machine
        return machine, None

    def _executable(self, context: LaunchContext, remote: bool) -> Executable:
        """What runs it: a command (no package, as launch_ros has it), or the package's
        executable, found here; one on another host is found there (its words are not
        known here)."""
        if self.package is None:  # launch_ros: the executable is run as a command
            command = perform_text(context, self.executable)
            return Executable(os.path.basename(command), (command,))
        name = perform_text(context, self.executable)
        if remote:
            return Executable(name, ())
        return find_executable(context.packages.get(perform_text(context, self.package)), name)

    def _remote_start(self, context: LaunchContext, at: int, argv: list[str],
                      words: list[str]) -> RemoteStart:
        """How it starts on another host: its package's executable found there, its words
        at `at`, and its parameter files sent along (a ROS 1 node's are in its environment)."""
        if self.package is None:
            return RemoteStart(None, None, files=params_files(argv, words))
        return RemoteStart(perform_text(context, self.package),
                           perform_text(context, self.executable), at,
                           params_files(argv, words))

    def _place(self, context: LaunchContext, spec: ProcessSpec, name: str, home: str) -> None:
        """A ROS 1 node whose machine was declared after it, placed once the launch files
        are read: on another host as made, or, on this host after all, found here."""
        try:
            spec.machine = lookup(context, name)
            if spec.machine.local and spec.remote is not None:
                start, spec.remote = spec.remote, None
                if start.package is not None:
                    found = find_executable(context.packages.get(start.package),
                                            start.executable or "")
                    spec.argv[start.at:start.at] = found.argv
                    spec.env = found.environment(spec.env)
                spec.cwd = self._ros1_cwd(home, spec.argv[0], spec.env)
                check_runnable(spec.argv[0], spec.env, spec.cwd)
        except LaunchError as exc:
            raise exc.at(self.where) from None

    def _ros1_words(self, context: LaunchContext, value: Any) -> list[str]:
        """roslaunch's node args and launch-prefix: the text, substituted, then split as a
        shell would (shlex)."""
        if value is None:
            return []
        text = perform_text(context, to_text(value))
        try:
            import shlex

            return shlex.split(text)
        except ValueError as exc:
            raise ExecutionError(f"cannot split '{text}' into words: {exc}") from None

    def _home(self, context: LaunchContext) -> str:
        """roslaunch's cwd word: ROS_HOME or node."""
        return perform_text(context, self.home) if self.home is not None else "ROS_HOME"

    @staticmethod
    def _ros1_cwd(word: str, program: str, env: dict[str, str]) -> str:
        """nodeprocess.LocalProcess.start: the node's folder for cwd="node", else ROS home
        (made when missing)."""
        if word == "node":
            return os.path.dirname(program) or "."
        home = env.get("ROS_HOME") or os.path.join(os.path.expanduser("~"), ".ros")
        os.makedirs(home, exist_ok=True)
        return home

    # --- what launch_ros's Node tells the Python API's users, once it has run ---------------
    @property
    def node_name(self) -> str:
        """Its full name (launch_ros's node_name), known once the action has run."""
        expanded = getattr(self, "_expanded", None)
        if expanded is None:
            raise RuntimeError("cannot access 'node_name' before executing action")
        space, name = expanded
        return f"{space.rstrip('/')}/{name}" if space.startswith("/") else f"{space}/{name}"

    @property
    def expanded_node_namespace(self) -> str:
        expanded = getattr(self, "_expanded", None)
        return UNSPECIFIED_SPACE if expanded is None else expanded[0]

    node_package = property(attrgetter("package"))
    node_executable = property(attrgetter("executable"))

    def is_node_name_fully_specified(self) -> bool:
        return UNSPECIFIED_NAME not in self.node_name and UNSPECIFIED_SPACE not in self.node_name

    def _node_name(self, context: LaunchContext) -> str:
        return perform_text(context, self.given_name) if self.given_name is not None else ""

    def _namespace(self, context: LaunchContext) -> str:
        own = perform_text(context, self.namespace) if self.namespace is not None else ""
        return params.join_namespace(params.namespace(context), own)

    def _parameter_arguments(self, context: LaunchContext, node: str, space: str,
                             stem: str) -> list[str]:
        """launch_ros's layout: the launch's `set_parameter`s as `-p name:=value` and its
        `set_parameters_from_file`s, in order, then one `--params-file` per `param` entry
        (keyed by the node's full name when its name and namespace are both known)."""
        words: list[str] = []
        for name, value in params.global_settings(context):
            if name == params.FILE:
                words += ["--params-file", os.path.abspath(value)]
            else:
                words += ["-p", params.parameter_argument(name, value)]
        known = bool(node) and bool(space or self.namespace is not None)
        key = f"{space.rstrip('/')}/{node}" if known else "/**"
        groups = parameter_groups(context, self.parameters, self.where)
        private = params.private_parameters(context)
        if private:  # roslaunch's ~names before it: as the node's first own <param>
            groups.insert(0, private)
        for group in groups:
            if isinstance(group, dict):
                if resolve(context, self.server, Kind.BOOL, "server"):
                    self._to_server(context, f"{space.rstrip('/')}/{stem}", group)
                group = params.write_params_file(params_folder(context), stem.strip("/") or
                                                 "node", group, key)
            words += ["--params-file", str(group)]
        return words

    @staticmethod
    def _to_server(context: LaunchContext, node: str, values: dict[str, Any]) -> None:
        for name, value in values.items():
            to_graph(context, f"{node}/{name.replace('.', '/')}", value)

    def _check_unique(self, context: LaunchContext, node: str, space: str) -> None:
        fqn = f"{space.rstrip('/')}/{node}" if space else f"/{node}"
        other = context.node_names.get(fqn)
        unique = resolve(context, self.unique, Kind.BOOL, "unique")
        # (roslaunch: any two, the same file included twice too; else: two places)
        if other is not None and (unique or other is not self.where):
            if unique:
                raise ExecutionError(
                    f"roslaunch file contains multiple nodes named [{fqn}]. Please check all "
                    "<node> 'name' attributes to make sure they are unique. Also check that "
                    f"$(anon id) use different ids. (the other is at {other})", self.where)
            context.log("WARN", f"two nodes are named '{fqn}': at {other} and at {self.where}")
        context.node_names.setdefault(fqn, self.where)
