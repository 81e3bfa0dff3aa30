"""launch_pytest.tools (launcher.compat.testing)."""

from launch_pytest.tools import process
from launcher.compat.testing.launch_pytest import tools as _tools
from launcher.compat.testing.launch_pytest.tools import *  # noqa: F403

__all__ = ["process", *_tools.__all__]
