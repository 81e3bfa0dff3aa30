"""launch_testing.active (launcher.compat.testing)."""

from launcher.compat.testing.active import Active  # noqa: F401
