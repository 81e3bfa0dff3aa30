"""launch_pytest.tools.process (launcher.compat.testing)."""

from launcher.compat.testing.launch_pytest import tools as _tools
from launcher.compat.testing.launch_pytest.tools import *  # noqa: F403
from launcher.compat.testing.launch_pytest.tools import register_event_handler

__all__ = [*_tools.__all__, "register_event_handler"]
