"""launch_testing_ros.LaunchTestRunner: launch_testing's runner (each run on a graph of its
own already: nothing ROS-specific to add)."""

from __future__ import annotations

import launch_testing.test_runner


class LaunchTestRunner(launch_testing.test_runner.LaunchTestRunner):
    pass


__all__ = ["LaunchTestRunner"]
