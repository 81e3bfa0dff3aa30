"""launch_testing.pytest.hookspecs (launcher.compat.testing)."""

from launcher.compat.testing.pytest_hookspecs import pytest_launch_collect_makemodule  # noqa: F401
