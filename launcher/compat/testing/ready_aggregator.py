"""launch_testing.ReadyAggregator: one ready function called after n others have been."""

from __future__ import annotations

import threading
from collections.abc import Callable


class ReadyAggregator:
    """Calls `ready_fn` on the `num_to_aggregate`-th call of its own `ready_fn`."""

    def __init__(self, ready_fn: Callable[[], object], num_to_aggregate: int) -> None:
        self._parent_ready_fn = ready_fn
        self._count_to_activate = num_to_aggregate
        self._lock = threading.Lock()

    def ready_fn(self) -> None:
        with self._lock:  # (the parent is called outside the lock: it may take it again)
            self._count_to_activate -= 1
            left = self._count_to_activate
        if left == 0:
            self._parent_ready_fn()
