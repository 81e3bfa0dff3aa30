"""launch.actions (launcher.api)."""

from launcher.api import (
    AppendEnvironmentVariable,
    DeclareLaunchArgument,
    EmitEvent,
    ExecuteLocal,
    ExecuteProcess,
    ForEach,
    ForLoop,
    GroupAction,
    IncludeLaunchDescription,
    Log,
    LogDebug,
    LogError,
    LogInfo,
    LogWarning,
    OpaqueCoroutine,
    OpaqueFunction,
    PopEnvironment,
    PopLaunchConfigurations,
    PushEnvironment,
    PushLaunchConfigurations,
    RegisterEventHandler,
    ResetEnvironment,
    ResetLaunchConfigurations,
    SetEnvironmentVariable,
    SetLaunchConfiguration,
    Shutdown,
    TimerAction,
    UnregisterEventHandler,
    UnsetEnvironmentVariable,
    UnsetLaunchConfiguration,
)

__all__ = [
    "AppendEnvironmentVariable", "DeclareLaunchArgument", "EmitEvent", "ExecuteLocal",
    "ExecuteProcess", "ForEach", "ForLoop", "GroupAction", "IncludeLaunchDescription", "Log",
    "LogDebug", "LogError", "LogInfo", "LogWarning", "OpaqueCoroutine", "OpaqueFunction",
    "PopEnvironment", "PopLaunchConfigurations", "PushEnvironment", "PushLaunchConfigurations",
    "RegisterEventHandler", "ResetEnvironment", "ResetLaunchConfigurations",
    "SetEnvironmentVariable", "SetLaunchConfiguration", "Shutdown", "TimerAction",
    "UnregisterEventHandler", "UnsetEnvironmentVariable", "UnsetLaunchConfiguration",
]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
