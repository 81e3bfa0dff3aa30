"""launch.substitutions (launcher.api)."""

from launcher.api import (
    AllSubstitution,
    AndSubstitution,
    AnonName,
    AnySubstitution,
    Command,
    EnvironmentVariable,
    EqualsSubstitution,
    FileContent,
    FindExecutable,
    ForEachVar,
    ForLoopIndex,
    IfElseSubstitution,
    LaunchConfiguration,
    LaunchLogDir,
    LocalSubstitution,
    NotEqualsSubstitution,
    NotSubstitution,
    OrSubstitution,
    PathJoinSubstitution,
    PathSubstitution,
    PythonExpression,
    StringJoinSubstitution,
    StringStripSubstitution,
    SubstitutionFailure,
    TextSubstitution,
    ThisLaunchFile,
    ThisLaunchFileDir,
)

__all__ = [
    "AllSubstitution", "AndSubstitution", "AnonName", "AnySubstitution", "Command",
    "EnvironmentVariable", "EqualsSubstitution", "FileContent", "FindExecutable", "ForEachVar",
    "ForLoopIndex", "IfElseSubstitution", "LaunchConfiguration", "LaunchLogDir",
    "LocalSubstitution", "NotEqualsSubstitution", "NotSubstitution", "OrSubstitution",
    "PathJoinSubstitution", "PathSubstitution", "PythonExpression", "StringJoinSubstitution",
    "StringStripSubstitution", "SubstitutionFailure", "TextSubstitution", "ThisLaunchFile",
    "ThisLaunchFileDir",
]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
