"""launch_ros.actions (launcher.api)."""

from launcher.api import (  # noqa: F401
    ComposableNodeContainer,
    LifecycleNode,
    LoadComposableNodes,
    Node,
    PushRosNamespace,
    SetParameter,
    SetParametersFromFile,
    SetRemap,
    SetUseSimTime,
)
