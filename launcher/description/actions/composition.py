"""Composition, as launch_ros does it: `node_container` runs a component container and loads its
`composable_node`s into it; `load_composable_node` loads more into a running container.

    - node_container:
        pkg: rclcpp_components
        exec: component_container
        name: robot_container
        namespace: r1
        composable_node:
          - {pkg: robot_state_publisher, plugin: robot_state_publisher::RobotStatePublisher,
             name: robot_state_publisher, param: [{name: robot_description, value: …}]}
    - load_composable_node:
        target: /r1/robot_container
        composable_node: [{pkg: robot_application, plugin: robot_application::Driver}]

A composable node takes the launch's namespace, `set_remap`s and `set_parameter`s as a node
does. Its plugin is checked against what the package declares before the container is asked
(a located error, with did-you-mean); the container's answer for each node is logged, and a
failure is reported at the composable_node, the rest of the launch going on.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launcher.description import parameters as params
from launcher.description.action import Action
from launcher.description.actions.entries import NameValue
from launcher.description.actions.node import Node, RemapEntry
from launcher.description.actions.param_entry import (
    ParamEntry,
    gather_parameters,
    python_parameters,
)
from launcher.description.condition import entry_applies, if_attr, unless_attr
from launcher.description.fields import Kind, attr
from launcher.description.registry import action
from launcher.description.ros_names import check_namespace, check_node_name
from launcher.description.substitution import perform_text, to_text
from launcher.errors import ExecutionError, LaunchError
from launcher.packages.components import find_component
from launcher.records import dataclass
from launcher.runtime.composition import LoadRequest
from launcher.runtime.context import LaunchContext


@dataclass(eq=False)
class ExtraArgument(NameValue):
    """An argument for the container about the node (use_intra_process_comms, …)."""


@dataclass(eq=False)
class ComposableNode:
    package: Any = attr(Kind.TEXT, name="pkg", aliases=("package",), required=True,
                        doc="The package declaring the component.")
    plugin: Any = attr(Kind.TEXT, required=True, doc="The component's plugin name (pkg::Name).")
    node_name: Any = attr(Kind.TEXT, name="name", doc="The node's name.")
    namespace: Any = attr(Kind.TEXT, aliases=("ns",), doc="The node's namespace.")
    parameters: list[Any] = attr(Kind.ENTRIES, name="param", entry=ParamEntry,
                                 doc="Parameters: name/value, nested, or from a file.")
    remappings: list[Any] = attr(Kind.ENTRIES, name="remap", entry=RemapEntry,
                                 doc="Topic and service remappings.")
    extra_arguments: list[Any] = attr(Kind.ENTRIES, name="extra_arg", entry=ExtraArgument,
                                      doc="Arguments for the container about this node.")
    only_if: Any = if_attr(name="if", doc="Loaded only when true (launch_ros's condition on a "
                                          "composable node).")
    only_unless: Any = unless_attr(name="unless", doc="Loaded only when false.")
    where: Any = None

    def __post_init__(self) -> None:
        self.parameters = python_parameters(self.parameters)
        self.remappings = [r if isinstance(r, RemapEntry) else
                           RemapEntry(to_text(r[0]), to_text(r[1])) for r in self.remappings]
        extras: list[Any] = []
        for entry in self.extra_arguments:  # Python: [{'use_intra_process_comms': True}]
            if isinstance(entry, dict):
                extras += [ExtraArgument(to_text(k), to_text(str(v).lower()
                                                             if isinstance(v, bool) else v))
                           for k, v in entry.items()]
            else:
                extras.append(entry)
        self.extra_arguments = extras
        for name in ("package", "plugin", "node_name", "namespace"):
            value = getattr(self, name)
            if value is not None and not isinstance(value, list):
                setattr(self, name, to_text(value))

    def request(self, context: LaunchContext) -> LoadRequest:
        """What the container is asked, with the launch's namespace, remaps and parameters."""
        package = perform_text(context, self.package)
        plugin = perform_text(context, self.plugin)
        if context.packages is not None:
            try:
                find_component(context.packages.get(package), plugin)
            except LaunchError as exc:
                raise ExecutionError(exc.message, exc.location or self.where) from None
        own = perform_text(context, self.namespace) if self.namespace is not None else ""
        node_name = perform_text(context, self.node_name) if self.node_name is not None else ""
        space = params.join_namespace(params.namespace(context), own)
        if self.node_name is not None:
            check_node_name(node_name, self.where)
        check_namespace(space, self.where)
        files, inline = gather_parameters(context, self.parameters, self.where)
        mine = [(perform_text(context, r.source), perform_text(context, r.target))
                for r in self.remappings]
        extra = {}
        for entry in self.extra_arguments:
            name = perform_text(context, entry.name)
            extra[name] = params.value_of(context, params.Written(entry.value), None, name)
        return LoadRequest(package, plugin, node_name, space,
                           [*mine, *params.remaps(context)],  # launch_ros's order: its own
                           inline, [str(f) for f in files],  # first (the first match wins)
                           extra, self.where)


def _requests(context: LaunchContext, nodes: list[ComposableNode],
              where: Any) -> list[LoadRequest]:
    """The requests; a node that cannot be asked for (an unknown plugin) is reported, and the
    others are loaded (as a container's refusal is)."""
    made = []
    for node in nodes:
        if not entry_applies(context, node):  # (switched off: the container starts all
            continue  # the same, as launch_ros's does)
        try:
            made.append(node.request(context))
        except LaunchError as exc:
            context.service.report(exc if exc.location else exc.at(node.where or where))
    return made


@action("node_container")
@dataclass(kw_only=True, eq=False)
class NodeContainer(Node):
    """A component container (rclcpp_components' component_container, or any executable that
    offers `~/_container/load_node`) with the composable nodes to load into it."""

    composable_nodes: list[Any] = attr(Kind.ENTRIES, name="composable_node",
                                       entry=ComposableNode, doc="The nodes to load into it.")
    fqn: str = ""  # the container's name, once started

    def spec(self, context: LaunchContext):  # type: ignore[override]
        node = self._node_name(context)
        if not node:  # said before anything is started
            raise ExecutionError("node_container needs a 'name': composable nodes are loaded "
                                 "into it by name", self.where)
        self.fqn = f"{self._namespace(context).rstrip('/')}/{node}"
        return super().spec(context)

    def started(self, context: LaunchContext, process: Any) -> None:
        requests = _requests(context, self.composable_nodes, self.where)
        alive: Callable[[], bool] = lambda: process.alive  # noqa: E731
        context.service.load_components(self.fqn, requests, alive)


@action("load_composable_node")
@dataclass(kw_only=True, eq=False)
class LoadComposableNodes(Action):
    target: Any = attr(Kind.TEXT, name="target", aliases=("target_container",), required=True,
                       doc="The container's node name (relative names take the namespace).")
    composable_nodes: list[Any] = attr(Kind.ENTRIES, name="composable_node",
                                       entry=ComposableNode, doc="The nodes to load.")

    container: Any = None  # Python: target_container=a ComposableNodeContainer action

    def __post_init__(self) -> None:
        if isinstance(self.target, NodeContainer):
            self.container, self.target = self.target, ""
        super().__post_init__()

    def execute(self, context: LaunchContext) -> Sequence[Action] | None:
        if context.service is None:
            return None
        target = self.container or self.target
        if isinstance(target, NodeContainer):  # Python: target_container=the action
            if not target.fqn:
                raise ExecutionError("load_composable_node: its target container has not "
                                     "been started", self.where)
            name = target.fqn
        else:
            name = params.join_namespace(params.namespace(context),
                                         perform_text(context, to_text(target)))
        requests = _requests(context, self.composable_nodes, self.where)
        process = next((p for p in reversed(context.service.processes)
                        if getattr(p.spec.origin, "fqn", None) == name), None)
        alive = (lambda: process.alive) if process is not None else None
        context.service.load_components(name, requests, alive)
        return None
