"""launch_testing.pytest.hooks (launcher.compat.testing)."""

from launcher.compat.testing.loader import LoadTestsFromPythonModule
from launcher.compat.testing.pytest_hooks import (
    LaunchTestFailure,
    LaunchTestFailureRepr,
    LaunchTestItem,
    LaunchTestModule,
    find_launch_test_entrypoint,
    pytest_addhooks,
    pytest_addoption,
    pytest_configure,
    pytest_launch_collect_makemodule,
    pytest_pycollect_makemodule,
)
from launcher.compat.testing.test_runner import LaunchTestRunner

__all__ = [
    "LaunchTestFailure", "LaunchTestFailureRepr", "LaunchTestItem", "LaunchTestModule",
    "LaunchTestRunner", "LoadTestsFromPythonModule", "find_launch_test_entrypoint",
    "pytest_addhooks", "pytest_addoption", "pytest_configure",
    "pytest_launch_collect_makemodule", "pytest_pycollect_makemodule"
]
