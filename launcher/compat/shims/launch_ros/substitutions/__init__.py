"""launch_ros.substitutions (launcher.api)."""

from launcher.api import ExecutableInPackage, FindPackage, FindPackagePrefix, FindPackageShare
from launcher.api.substitutions import RosParameter as Parameter

__all__ = ["ExecutableInPackage", "FindPackage", "FindPackagePrefix", "FindPackageShare",
           "Parameter"]


from launcher.compat.finder import rest_from_layout  # noqa: E402

__getattr__ = rest_from_layout(__name__)
