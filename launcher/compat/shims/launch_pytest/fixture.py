"""launch_pytest.fixture (launcher.compat.testing)."""

from launcher.compat.testing.launch_pytest.fixture import (
    finalize_launch_service,
    fixture,
    get_event_loop_fixture,
    get_launch_context_fixture,
    get_launch_service_fixture,
    scope_gt,
)

__all__ = [
    "finalize_launch_service", "fixture", "get_event_loop_fixture",
    "get_launch_context_fixture", "get_launch_service_fixture", "scope_gt"
]
