"""launch_pytest over launcher's launch service: `@launch_pytest.fixture` gives a launch
description that tests marked `@pytest.mark.launch(fixture=…)` run beside (or after, with
`shutdown=True`), in a thread of its own, on a graph of its own for the pytest session. A real
launch_pytest that the user installed wins in their shell.
The machinery is launcher.compat.testing's; this package gives it launch_pytest's names."""

from launch_pytest import actions, tools
from launcher.compat.testing.launch_pytest.fixture import fixture

__all__ = ["actions", "fixture", "tools"]
