"""launch_ros.substitutions (launcher.api)."""

from launcher.api import FindPackagePrefix, FindPackageShare  # noqa: F401
