"""launch_ros.actions (launcher.api)."""

from launcher.api import (
    ComposableNodeContainer,
    LifecycleNode,
    LifecycleTransition,
    LoadComposableNodes,
    Node,
    PushROSNamespace,
    PushRosNamespace,
    ROSTimer,
    RosTimer,
    SetParameter,
    SetParametersFromFile,
    SetRemap,
    SetROSLogDir,
    SetUseSimTime,
)

__all__ = ["ComposableNodeContainer", "LifecycleNode", "LifecycleTransition",
           "LoadComposableNodes", "Node", "PushROSNamespace", "PushRosNamespace", "ROSTimer",
           "RosTimer", "SetParameter", "SetParametersFromFile", "SetROSLogDir", "SetRemap",
           "SetUseSimTime"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
