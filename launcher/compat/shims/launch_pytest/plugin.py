"""launch_pytest.plugin (launcher.compat.testing)."""

from launcher.compat.testing.actions import ReadyToTest  # noqa: F401
from launcher.compat.testing.launch_pytest.fixture import (
    finalize_launch_service,
    get_event_loop_fixture,
    get_launch_context_fixture,
    get_launch_service_fixture,
)
from launcher.compat.testing.launch_pytest.helpers import (
    LaunchTestWarning,
    event_loop,
    from_parent,
    get_launch_test_fixture,
    get_launch_test_fixturename,
    get_ready_to_test_action,
    has_shutdown_kwarg,
    is_launch_test,
    is_launch_test_mark_valid,
    is_same_launch_test_fixture,
    is_shutdown_test,
    is_valid_test_item,
    iterate_ready_to_test_actions,
    launch_context,
    launch_service,
    need_shutdown_test_item,
    run_until_complete,
    transfer_markers,
    wrap_asyncgen,
    wrap_asyncgen_fscope,
    wrap_coroutine,
    wrap_func,
    wrap_generator,
    wrap_generator_fscope,
)
from launcher.compat.testing.launch_pytest.plugin import (
    pytest_collection_modifyitems,
    pytest_configure,
    pytest_fixture_setup,
    pytest_pycollect_makeitem,
    pytest_pyfunc_call,
)

__all__ = [
    "LaunchTestWarning", "event_loop", "finalize_launch_service", "from_parent",
    "get_event_loop_fixture", "get_launch_context_fixture", "get_launch_service_fixture",
    "get_launch_test_fixture", "get_launch_test_fixturename", "get_ready_to_test_action",
    "has_shutdown_kwarg", "is_launch_test", "is_launch_test_mark_valid",
    "is_same_launch_test_fixture", "is_shutdown_test", "is_valid_test_item",
    "iterate_ready_to_test_actions", "launch_context", "launch_service",
    "need_shutdown_test_item", "pytest_collection_modifyitems", "pytest_configure",
    "pytest_fixture_setup", "pytest_pycollect_makeitem", "pytest_pyfunc_call",
    "run_until_complete", "transfer_markers", "wrap_asyncgen", "wrap_asyncgen_fscope",
    "wrap_coroutine", "wrap_func", "wrap_generator", "wrap_generator_fscope"
]
