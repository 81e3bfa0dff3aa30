"""launch.conditions (launcher.api)."""

from launcher.api import IfCondition, UnlessCondition  # noqa: F401
