"""launch_testing over launcher's launch service: a test file's `generate_test_description`
is launched, its active tests run while it runs, its post-shutdown tests after it ends
(`launch_test FILE`, `ros2 test FILE`, `python -m launch_testing.launch_test FILE`, or plain
`pytest FILE`). A real launch_testing that the user installed wins in their shell.
The machinery is launcher.compat.testing's; this package gives it launch_testing's names."""

from launch_testing import actions, asserts, markers, tools, util
from launcher.compat.testing.io_handler import ActiveIoHandler, IoHandler
from launcher.compat.testing.markers import (
    parametrize,
    post_shutdown_test,
    ready_to_test_action_timeout,
)
from launcher.compat.testing.proc_info_handler import ActiveProcInfoHandler, ProcInfoHandler
from launcher.compat.testing.ready_aggregator import ReadyAggregator

__all__ = [
    "ActiveIoHandler", "ActiveProcInfoHandler", "IoHandler", "ProcInfoHandler",
    "ReadyAggregator", "actions", "asserts", "markers", "parametrize", "post_shutdown_test",
    "ready_to_test_action_timeout", "tools", "util"
]
