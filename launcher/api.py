"""The Python API for launch files: `generate_launch_description()` returns one of these.

Names and keyword arguments follow ROS 2's `launch` package, so a ROS 2 user's habits carry
over (`DeclareLaunchArgument('x', default_value='1')`, `LaunchConfiguration('x')`, …).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from launcher.description import action as _action
from launcher.description.actions import arguments as _arguments
from launcher.description.actions import composition as _composition
from launcher.description.actions import environment as _environment
from launcher.description.actions import group as _group
from launcher.description.actions import lifecycle as _lifecycle
from launcher.description.actions import log as _log
from launcher.description.actions import loops as _loops
from launcher.description.actions import node as _node
from launcher.description.actions import param_entry as _params
from launcher.description.actions import ros as _ros
from launcher.description.actions import shutdown as _shutdown
from launcher.description.actions import timer as _timer
from launcher.description.actions.event_handlers import (
    OnProcessExit,
    OnProcessIO,
    OnProcessStart,
    OnShutdown,
    RegisterEventHandler,
)
from launcher.description.actions.executable import ExecuteProcess
from launcher.description.actions.include import IncludeLaunchDescription
from launcher.description.actions.opaque import OpaqueFunction
from launcher.description.condition import Condition as _Condition
from launcher.description.condition import IfCondition, UnlessCondition
from launcher.description.substitution import Substitution, Text, to_text
from launcher.description.substitutions import command as _command
from launcher.description.substitutions import configuration as _configuration
from launcher.description.substitutions import environment as _env
from launcher.description.substitutions import expression as _expression
from launcher.description.substitutions import files as _files
from launcher.description.substitutions import packages as _packages

Action = _action.Action  # launch.Action: the base of an action of the user's own
LaunchDescription = _action.LaunchDescription
PathJoinSubstitution = _files.PathJoinSubstitution

__all__ = [
    "Action", "AppendEnvironmentVariable", "AnyLaunchDescriptionSource", "Command",
    "DeclareLaunchArgument", "EnvironmentVariable", "ExecuteProcess", "FindExecutable",
    "ForEach", "ForLoop", "GroupAction", "IfCondition", "IncludeLaunchDescription",
    "LaunchConfiguration", "LaunchDescription", "LaunchDescriptionSource", "LogInfo",
    "OnProcessExit", "OnProcessIO", "OnProcessStart", "OnShutdown", "OpaqueFunction",
    "PathJoinSubstitution", "PythonExpression", "PythonLaunchDescriptionSource",
    "RegisterEventHandler", "ResetEnvironment", "ResetLaunchConfigurations",
    "SetEnvironmentVariable", "SetLaunchConfiguration", "Shutdown", "Substitution",
    "TextSubstitution", "ThisLaunchFileDir", "TimerAction", "UnlessCondition",
    "UnsetEnvironmentVariable", "XMLLaunchDescriptionSource", "YAMLLaunchDescriptionSource",
    "Node", "ComposableNodeContainer", "LoadComposableNodes", "ComposableNode",
    "FindPackageShare", "FindPackagePrefix", "ParameterFile", "ParameterValue", "PushRosNamespace",
    "SetParameter", "SetRemap", "SetUseSimTime", "SetParametersFromFile", "LifecycleNode",
    "EmitEvent", "ChangeState", "OnStateTransition", "matches_action",
]


# --- sources for IncludeLaunchDescription ---------------------------------------------------
class LaunchDescriptionSource:
    """Where an included description comes from: a path (text or substitutions)."""

    def __init__(self, location: Any) -> None:
        self.location = location


PythonLaunchDescriptionSource = AnyLaunchDescriptionSource = LaunchDescriptionSource
XMLLaunchDescriptionSource = YAMLLaunchDescriptionSource = LaunchDescriptionSource


# --- actions ------------------------------------------------------------------------------
def DeclareLaunchArgument(name: str, default_value: Any = None, description: str = "",  # noqa: N802
                          choices: Sequence[str] = (), **kw: Any) -> Any:
    return _arguments.DeclareLaunchArgument(name=name, default_value=default_value,
                                            description=description, choices=list(choices), **kw)


def SetLaunchConfiguration(name: Any, value: Any, **kw: Any) -> Any:  # noqa: N802
    return _arguments.SetLaunchConfiguration(name=name, value=value, **kw)


def ResetLaunchConfigurations(launch_configurations: dict | None = None, **kw: Any) -> Any:  # noqa: N802
    keep = [_arguments.KeepEntry(to_text(k), to_text(v))
            for k, v in (launch_configurations or {}).items()]
    return _arguments.ResetLaunchConfigurations(keep=keep, **kw)


def GroupAction(actions: Sequence[Any], *, scoped: bool = True, forwarding: bool = True,  # noqa: N802
                launch_configurations: dict | None = None, **kw: Any) -> Any:
    return _group.GroupAction(actions=list(actions), scoped=scoped, forwarding=forwarding,
                              keep=dict(launch_configurations or {}), **kw)


def TimerAction(*, period: Any, actions: Sequence[Any], cancel_on_shutdown: bool = True,  # noqa: N802
                **kw: Any) -> Any:
    return _timer.TimerAction(period=period, actions=list(actions),
                              cancel_on_shutdown=cancel_on_shutdown, **kw)


def SetEnvironmentVariable(name: Any, value: Any, **kw: Any) -> Any:  # noqa: N802
    return _environment.SetEnvironmentVariable(name=name, value=value, **kw)


def UnsetEnvironmentVariable(name: Any, **kw: Any) -> Any:  # noqa: N802
    return _environment.UnsetEnvironmentVariable(name=name, **kw)


def AppendEnvironmentVariable(name: Any, value: Any, prepend: Any = False,  # noqa: N802
                              separator: Any = ":", **kw: Any) -> Any:
    return _environment.AppendEnvironmentVariable(name=name, value=value, prepend=prepend,
                                                  separator=separator, **kw)


def ResetEnvironment(**kw: Any) -> Any:  # noqa: N802
    return _environment.ResetEnvironment(**kw)


def LogInfo(*, msg: Any, **kw: Any) -> Any:  # noqa: N802
    return _log.LogInfo(msg=msg, **kw)


def Shutdown(*, reason: Any = None, **kw: Any) -> Any:  # noqa: N802
    return _shutdown.Shutdown(reason=None if reason is None else to_text(reason), **kw)


def ForLoop(length: Any, *, function: Callable[[int], Any], name: str = "i",  # noqa: N802
            **kw: Any) -> Any:
    return _loops.ForLoop(length=to_text(length), name=name, function=function, **kw)


def ForEach(input_values: Any, *, function: Callable[..., Any], **kw: Any) -> Any:  # noqa: N802
    return _loops.ForEach(input_values=to_text(input_values), function=function, **kw)


# --- substitutions ------------------------------------------------------------------------
def _opt(value: Any) -> Any:
    return None if value is None else to_text(value)


def LaunchConfiguration(variable_name: Any, default: Any = None) -> Substitution:  # noqa: N802
    return _configuration.LaunchConfiguration(to_text(variable_name), _opt(default))


def EnvironmentVariable(name: Any, default_value: Any = None) -> Substitution:  # noqa: N802
    return _env.EnvironmentVariable(to_text(name), _opt(default_value))


def Command(command: Any, on_stderr: Any = "fail") -> Substitution:  # noqa: N802
    return _command.Command(to_text(command), to_text(on_stderr))


def PythonExpression(expression: Any) -> Substitution:  # noqa: N802
    """A restricted expression (see launcher.description.safe_expression), not Python eval."""
    return _expression.PythonExpression(to_text(expression))


def TextSubstitution(*, text: str) -> Substitution:  # noqa: N802
    return Text(text)


def FindExecutable(*, name: Any) -> Substitution:  # noqa: N802
    return _files.FindExecutable(to_text(name))


def ThisLaunchFileDir() -> Substitution:  # noqa: N802
    return _files.ThisLaunchFileDir()


def FindPackageShare(package: Any) -> Substitution:  # noqa: N802
    return _packages.FindPackageShare(to_text(package))


def FindPackagePrefix(package: Any) -> Substitution:  # noqa: N802
    return _packages.FindPackagePrefix(to_text(package))


# --- launch_ros ---------------------------------------------------------------------------
class ParameterValue:
    """A value with its type, as launch_ros has it: `ParameterValue(Command(…), value_type=str)`."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value, self.value_type = value, value_type

    def type_name(self) -> str | None:
        """`type:` as launch files write it: str, int, …, list_of_int, …"""
        names = {str: "str", int: "int", float: "float", bool: "bool"}
        if self.value_type is None:
            return None
        if self.value_type in names:
            return names[self.value_type]
        args = getattr(self.value_type, "__args__", ())
        if getattr(self.value_type, "__origin__", None) is list and args and args[0] in names:
            return f"list_of_{names[args[0]]}"
        raise TypeError(f"ParameterValue: value_type {self.value_type!r} is not one of str, "
                        "int, float, bool, List[str|int|float|bool]")


class ParameterFile:
    """A parameters file, as launch_ros has it: `ParameterFile(path, allow_substs=False)`;
    with `allow_substs` the substitutions written in the file are performed."""

    def __init__(self, param_file: Any, *, allow_substs: Any = False) -> None:
        self.param_file, self.allow_substs = param_file, allow_substs


def Node(*, executable: Any, package: Any = None, name: Any = None, namespace: Any = None,  # noqa: N802
         exec_name: Any = None, parameters: Sequence[Any] = (), remappings: Sequence[Any] = (),
         arguments: Sequence[Any] = (), ros_arguments: Sequence[Any] = (),
         _kind: type = _node.Node, **kw: Any) -> Any:
    return _kind(package=package, executable=executable, node_name=name,
                 namespace=namespace, exec_name=exec_name, parameters=_parameters(parameters),
                 remappings=list(remappings), arguments=list(arguments) or None,
                 ros_arguments=list(ros_arguments) or None, **kw)


def LifecycleNode(*, name: Any, namespace: Any, autostart: Any = False,  # noqa: N802
                  **kw: Any) -> Any:
    """launch_ros.actions.LifecycleNode: a Node the launch can drive through its states."""
    return Node(name=name, namespace=namespace, autostart=autostart,
                _kind=_lifecycle.LifecycleNode, **kw)


EmitEvent = _lifecycle.EmitEvent
ChangeState = _lifecycle.ChangeState
OnStateTransition = _lifecycle.OnStateTransition
matches_action = _lifecycle.matches_action


def ComposableNodeContainer(*, name: Any, namespace: Any,  # noqa: N802
                            package: Any = "rclcpp_components",
                            executable: Any = "component_container",
                            composable_node_descriptions: Sequence[Any] = (),
                            **kw: Any) -> Any:
    """launch_ros.actions.ComposableNodeContainer: a container and the nodes to load into it."""
    return Node(package=package, executable=executable, name=name, namespace=namespace,
                composable_nodes=list(composable_node_descriptions),
                _kind=_composition.NodeContainer, **kw)


def LoadComposableNodes(*, composable_node_descriptions: Sequence[Any],  # noqa: N802
                        target_container: Any, **kw: Any) -> Any:
    """launch_ros.actions.LoadComposableNodes: load into a running container (its name, or
    the ComposableNodeContainer action)."""
    return _composition.LoadComposableNodes(target=target_container,
                                            composable_nodes=list(composable_node_descriptions),
                                            **kw)


def ComposableNode(*, package: Any, plugin: Any, name: Any = None,  # noqa: N802
                   namespace: Any = None, parameters: Sequence[Any] = (),
                   remappings: Sequence[Any] = (), extra_arguments: Sequence[Any] = (),
                   condition: Any = None) -> Any:
    """launch_ros.descriptions.ComposableNode (`condition`: IfCondition or UnlessCondition,
    as launch_ros takes it: loaded only when it holds)."""
    switch: dict[str, Any] = {}
    if condition is not None:
        if not isinstance(condition, _Condition):
            raise TypeError(f"ComposableNode(condition=...): expected IfCondition(...) or "
                            f"UnlessCondition(...), got {type(condition).__name__}")
        switch["only_unless" if condition.negate else "only_if"] = condition.text
    return _composition.ComposableNode(package=package, plugin=plugin, node_name=name,
                                       namespace=namespace, parameters=_parameters(parameters),
                                       remappings=list(remappings),
                                       extra_arguments=list(extra_arguments), **switch)


def _parameters(parameters: Sequence[Any]) -> list[Any]:
    """launch_ros's `parameters=[{...}, 'file.yaml']`: each dict one group (one params file)."""
    entries = []
    for item in parameters:
        if isinstance(item, dict):
            entries.append(_params.ParamEntry(children=_parameter_group(item), group=True))
        elif isinstance(item, ParameterFile):
            entries.append(_params.ParamEntry(from_file=to_text(item.param_file),
                                              allow_substs=to_text(item.allow_substs)
                                              if item.allow_substs else None))
        else:
            entries.append(_params.ParamEntry(from_file=to_text(item)))
    return entries


def _parameter_group(values: dict[Any, Any]) -> list[Any]:
    out = []
    for name, value in values.items():
        if isinstance(value, dict):
            out.append(_params.ParamEntry(name=to_text(name), children=_parameter_group(value)))
        elif isinstance(value, ParameterValue):
            out.append(_params.python_parameter(name, value.value, value.type_name()))
        else:
            out.append(_params.python_parameter(name, value))
    return out


def PushRosNamespace(namespace: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.PushRosNamespace(namespace=namespace, **kw)


def SetParameter(name: Any, value: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetParameter(name=name, value=value, **kw)


def SetParametersFromFile(filename: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetParametersFromFile(filename=filename, **kw)


def SetRemap(src: Any, dst: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetRemap(source=src, target=dst, **kw)


def SetUseSimTime(value: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetUseSimTime(value=value, **kw)
