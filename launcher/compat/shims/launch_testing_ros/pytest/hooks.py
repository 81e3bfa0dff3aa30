"""launch_testing_ros.pytest.hooks: launch_testing's module and item, with this package's
LaunchTestRunner."""

from __future__ import annotations

from typing import Any

from launch_testing.pytest.hooks import LaunchTestItem, LaunchTestModule

from launch_testing_ros.test_runner import LaunchTestRunner


class LaunchROSTestItem(LaunchTestItem):
    @classmethod
    def from_parent(cls, *args: Any, **kwargs: Any) -> Any:  # type: ignore[override]
        kwargs["runner_cls"] = LaunchTestRunner
        return super().from_parent(*args, **kwargs)


class LaunchROSTestModule(LaunchTestModule):
    def makeitem(self, *args: Any, **kwargs: Any) -> Any:
        return LaunchROSTestItem.from_parent(*args, **kwargs)


__all__ = ["LaunchROSTestItem", "LaunchROSTestModule", "LaunchTestRunner"]
