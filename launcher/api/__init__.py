"""The Python API for launch files: `generate_launch_description()` returns one of these.

Names and keyword arguments follow ROS 2's `launch` package, so a ROS 2 user's habits carry
over (`DeclareLaunchArgument('x', default_value='1')`, `LaunchConfiguration('x')`, …).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any, Union

from launcher.api.actions import (
    Executable,
    ExecuteLocal,
    OpaqueCoroutine,
    PopEnvironment,
    PopLaunchConfigurations,
    PushEnvironment,
    PushLaunchConfigurations,
    ReplaceEnvironmentVariables,
    UnsetLaunchConfiguration,
)
from launcher.api.ros import (
    LifecycleTransition,
    Parameter,
    ParameterFile,
    ParameterValue,
    ROSTimer,
    RosTimer,
    SetROSLogDir,
    matches_node_name,
)
from launcher.api.sources import (
    AnyLaunchDescriptionSource,
    FrontendLaunchDescriptionSource,
    InvalidLaunchFileError,
    LaunchDescriptionSource,
    PythonLaunchDescriptionSource,
    XMLLaunchDescriptionSource,
    YAMLLaunchDescriptionSource,
)
from launcher.api.substitutions import (
    AllSubstitution,
    AndSubstitution,
    AnonName,
    AnySubstitution,
    Command,
    ContainerSubstitution,
    EnvironmentVariable,
    EqualsSubstitution,
    ExecutableInPackage,
    FileContent,
    FindExecutable,
    FindPackage,
    FindPackagePrefix,
    FindPackageShare,
    ForEachVar,
    ForLoopIndex,
    IfElseSubstitution,
    LaunchConfiguration,
    LaunchLogDir,
    LeftRightLogicalSubstitution,
    LocalSubstitution,
    NotEqualsSubstitution,
    NotSubstitution,
    OrSubstitution,
    PathJoinSubstitution,
    PathSubstitution,
    PythonExpression,
    StringJoinSubstitution,
    StringStripSubstitution,
    Substitution,
    SubstitutionFailure,
    TextSubstitution,
    ThisLaunchFile,
    ThisLaunchFileDir,
)
from launcher.api.utilities import AsyncSafeSignalManager
from launcher.description import action as _action
from launcher.description.actions import arguments as _arguments
from launcher.description.actions import composition as _composition
from launcher.description.actions import environment as _environment
from launcher.description.actions import group as _group
from launcher.description.actions import lifecycle as _lifecycle
from launcher.description.actions import loops as _loops
from launcher.description.actions import node as _node
from launcher.description.actions import param_entry as _params
from launcher.description.actions import ros as _ros
from launcher.description.actions import shutdown as _shutdown
from launcher.description.actions import timer as _timer
from launcher.description.actions.event_handlers import (
    BaseEventHandler,
    EventHandler,
    OnActionEventBase,
    OnExecutionComplete,
    OnIncludeLaunchDescription,
    OnProcessExit,
    OnProcessIO,
    OnProcessStart,
    OnShutdown,
    RegisterEventHandler,
    UnregisterEventHandler,
    event_named,
    gen_handler,
)
from launcher.description.actions.executable import ExecuteProcess
from launcher.description.actions.include import IncludeLaunchDescription
from launcher.description.actions.log import Log, LogDebug, LogError, LogInfo, LogWarning
from launcher.description.actions.opaque import OpaqueFunction
from launcher.description.condition import (
    Condition,
    IfCondition,
    LaunchConfigurationEquals,
    LaunchConfigurationNotEquals,
    UnlessCondition,
)
from launcher.description.condition import TextCondition as _TextCondition
from launcher.description.substitution import to_text

SomeSubstitutionsType = Union[str, Substitution, Iterable[Union[str, Substitution]]]  # noqa: UP007
SomeSubstitutionsType_types_tuple = (str, Substitution, Iterable)
SomeEntitiesType = Union[_action.LaunchDescriptionEntity,  # noqa: UP007
                         Iterable[_action.LaunchDescriptionEntity]]
SomeEntitiesType_types_tuple = (_action.LaunchDescriptionEntity, Iterable)

Action = _action.Action  # launch.Action: the base of an action of the user's own
LaunchDescription = _action.LaunchDescription
LaunchDescriptionEntity = _action.LaunchDescriptionEntity

# --- actions ------------------------------------------------------------------------------
def DeclareLaunchArgument(name: str, default_value: Any = None, description: str = "",  # noqa: N802
                          choices: Sequence[str] = (), **kw: Any) -> Any:
    return _arguments.DeclareLaunchArgument(name=name, default_value=default_value,
                                            given_description=description,
                                            choices=list(choices), **kw)


def SetLaunchConfiguration(name: Any, value: Any, **kw: Any) -> Any:  # noqa: N802
    return _arguments.SetLaunchConfiguration(name=name, value=value, **kw)


def ResetLaunchConfigurations(launch_configurations: dict | None = None, **kw: Any) -> Any:  # noqa: N802
    keep = [_arguments.KeepEntry(to_text(k), to_text(v))
            for k, v in (launch_configurations or {}).items()]
    return _arguments.ResetLaunchConfigurations(keep=keep, **kw)


def _no_machine(kw: dict[str, Any], name: str) -> None:
    """launch's and launch_ros's own classes take no machine= (ROS 2 has no multi-host
    launch): a file that says it would not run under ros2 launch either."""
    if "machine" in kw:
        raise TypeError(f"{name}() got an unexpected keyword argument 'machine' (a machine is "
                        "launcher's extension: from launcher.api.extensions import PushMachine,"
                        f" and put PushMachine('…') before the {name} in a GroupAction)")


def GroupAction(actions: Sequence[Any], *, scoped: bool = True, forwarding: bool = True,  # noqa: N802
                launch_configurations: dict | None = None, **kw: Any) -> Any:
    _no_machine(kw, "GroupAction")
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


def Shutdown(*, reason: Any = None, **kw: Any) -> Any:  # noqa: N802
    return _shutdown.Shutdown(reason=None if reason is None else to_text(reason), **kw)


def ForLoop(length: Any, *, function: Callable[[int], Any], name: str = "i",  # noqa: N802
            **kw: Any) -> Any:
    return _loops.ForLoop(length=to_text(length), name=name, function=function, **kw)


def ForEach(input_values: Any, *, function: Callable[..., Any], **kw: Any) -> Any:  # noqa: N802
    return _loops.ForEach(input_values=to_text(input_values), function=function, **kw)


# --- launch_ros ---------------------------------------------------------------------------
def Node(*, executable: Any, package: Any = None, name: Any = None, namespace: Any = None,  # noqa: N802
         exec_name: Any = None, parameters: Sequence[Any] = (), remappings: Sequence[Any] = (),
         arguments: Sequence[Any] = (), ros_arguments: Sequence[Any] = (),
         _kind: type = _node.Node, **kw: Any) -> Any:
    _no_machine(kw, "Node")
    return _kind(package=package, executable=executable, given_name=name,
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
        if not isinstance(condition, _TextCondition):
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
        elif isinstance(item, Parameter):
            entries.append(_params.ParamEntry(children=_parameter_group(item.as_dict()),
                                              group=True))
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


def PushROSNamespace(namespace: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.PushRosNamespace(namespace=namespace, **kw)


PushRosNamespace = PushROSNamespace  # (its name before Jazzy)


def SetParameter(name: Any, value: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetParameter(name=name, value=value, **kw)


def SetParametersFromFile(filename: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetParametersFromFile(filename=filename, **kw)


def SetRemap(src: Any, dst: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetRemap(source=src, target=dst, **kw)


def SetUseSimTime(value: Any, **kw: Any) -> Any:  # noqa: N802
    return _ros.SetUseSimTime(value=value, **kw)


__all__ = [
    "SomeEntitiesType", "SomeEntitiesType_types_tuple", "SomeSubstitutionsType",
    "SomeSubstitutionsType_types_tuple",
    "LifecycleTransition", "Parameter", "ROSTimer", "RosTimer", "SetROSLogDir",
    "matches_node_name", "PushROSNamespace",
    "ContainerSubstitution", "LeftRightLogicalSubstitution", "gen_handler",
    "AsyncSafeSignalManager",
    "Action", "AllSubstitution", "AndSubstitution", "AnonName", "AnyLaunchDescriptionSource",
    "AnySubstitution", "AppendEnvironmentVariable", "BaseEventHandler", "ChangeState",
    "Command", "ComposableNode", "ComposableNodeContainer", "Condition",
    "DeclareLaunchArgument", "EmitEvent", "EnvironmentVariable", "EqualsSubstitution",
    "EventHandler", "Executable", "ExecutableInPackage", "ExecuteLocal", "ExecuteProcess",
    "FileContent", "FindExecutable", "FindPackage", "FindPackagePrefix", "FindPackageShare",
    "ForEach", "ForEachVar", "ForLoop", "ForLoopIndex", "FrontendLaunchDescriptionSource",
    "GroupAction", "IfCondition", "IfElseSubstitution", "IncludeLaunchDescription",
    "InvalidLaunchFileError", "LaunchConfiguration", "LaunchConfigurationEquals",
    "LaunchConfigurationNotEquals", "LaunchDescription", "LaunchDescriptionEntity",
    "LaunchDescriptionSource", "LaunchLogDir", "LifecycleNode", "LoadComposableNodes",
    "LocalSubstitution", "Log", "LogDebug", "LogError", "LogInfo", "LogWarning", "Node",
    "NotEqualsSubstitution", "NotSubstitution", "OnActionEventBase", "OnExecutionComplete",
    "OnIncludeLaunchDescription", "OnProcessExit", "OnProcessIO", "OnProcessStart",
    "OnShutdown", "OnStateTransition", "OpaqueCoroutine", "OpaqueFunction", "OrSubstitution",
    "ParameterFile", "ParameterValue", "PathJoinSubstitution", "PathSubstitution",
    "PopEnvironment", "PopLaunchConfigurations", "PushEnvironment", "PushLaunchConfigurations",
    "PushRosNamespace", "PythonExpression", "PythonLaunchDescriptionSource",
    "RegisterEventHandler", "ReplaceEnvironmentVariables", "ResetEnvironment",
    "ResetLaunchConfigurations", "SetEnvironmentVariable", "SetLaunchConfiguration",
    "SetParameter", "SetParametersFromFile", "SetRemap", "SetUseSimTime", "Shutdown",
    "StringJoinSubstitution", "StringStripSubstitution", "Substitution", "SubstitutionFailure",
    "TextSubstitution", "ThisLaunchFile", "ThisLaunchFileDir", "TimerAction",
    "UnlessCondition", "UnregisterEventHandler", "UnsetEnvironmentVariable",
    "UnsetLaunchConfiguration", "XMLLaunchDescriptionSource", "YAMLLaunchDescriptionSource",
    "event_named", "matches_action",
]
