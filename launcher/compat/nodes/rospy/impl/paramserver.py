"""rospy.impl.paramserver: a cache of the parameter tree (rospy's get_param_cached fills
it; launcher's get_param_cached reads fresh values), a thread-safe nested dictionary."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from rospy.names import GLOBALNS, SEP


class ParamServerCache:
    """Cached values as a tree of dictionaries; `notifier(key, value)` hears each update."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.d: dict[str, Any] | None = None
        self.notifier: Callable[[str, Any], Any] | None = None

    def _parent(self, key: str, make: bool) -> tuple[dict[str, Any], str]:
        """The dictionary that holds `key`'s last part, and that part (KeyError when a
        namespace on the way is missing and not `make`)."""
        *namespaces, last = [x for x in key.split(SEP) if x]
        if self.d is None:
            if not make:
                raise KeyError(key)
            self.d = {}
        d = self.d
        for ns in namespaces:
            if not isinstance(d.get(ns), dict):
                if not make:
                    raise KeyError(key)
                d[ns] = {}
            d = d[ns]
        return d, last

    def delete(self, key: str) -> None:
        with self.lock:
            if key == GLOBALNS:
                raise KeyError("cannot delete root of parameter tree")
            d, last = self._parent(key, make=False)
            del d[last]

    def set_notifier(self, notifier: Callable[[str, Any], Any]) -> None:
        """Call `notifier(key, value)` (under the lock: keep it short) on each update."""
        self.notifier = notifier

    def update(self, key: str, value: Any) -> None:
        """Change a cached value (KeyError when it is not cached), then notify."""
        with self.lock:
            d, last = self._parent(key, make=False)
            if last not in d:
                raise KeyError(key)
            d[last] = value
            if self.notifier is not None:
                self.notifier(key, value)

    def set(self, key: str, value: Any) -> None:
        """Cache a value (the prerequisite of update)."""
        with self.lock:
            if key == GLOBALNS:
                if not isinstance(value, dict):
                    raise TypeError("cannot set root of parameter tree to non-dictionary")
                self.d = value
                return
            d, last = self._parent(key, make=True)
            d[last] = value

    def get(self, key: str) -> Any:
        """The cached value; KeyError when it is not cached."""
        with self.lock:
            if self.d is None:
                raise KeyError(key)
            if key == GLOBALNS:
                value = self.d
            else:
                d, last = self._parent(key, make=False)
                value = d[last]
            if isinstance(value, dict) and not value:
                raise KeyError(key)  # an empty namespace is not a value
            return value


_param_server_cache: list[ParamServerCache] = []


def get_param_server_cache() -> ParamServerCache:
    """The process's one cache."""
    if not _param_server_cache:
        _param_server_cache.append(ParamServerCache())
    return _param_server_cache[0]
