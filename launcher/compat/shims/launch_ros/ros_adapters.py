"""launch_ros.ros_adapters (launcher.api.ros_adapter)."""

from launcher.api.ros_adapter import ROSAdapter, get_ros_adapter, get_ros_node

__all__ = ["ROSAdapter", "get_ros_adapter", "get_ros_node"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
