"""A publisher's watchers (lazy nodes) are told when subscribers come or all go; a word Zenoh
never sent, or one that came out of order, heals at the node's next recheck (the bus faked)."""

from __future__ import annotations

import threading
from types import SimpleNamespace

from launcher.bus.publisher import Publisher


def watched(zenoh_says: bool, told: bool) -> tuple[Publisher, list[bool]]:
    heard: list[bool] = []
    publisher = object.__new__(Publisher)
    publisher._watching = threading.Lock()
    publisher._closed = False
    publisher._watchers = [heard.append]
    publisher._told = told
    publisher._publisher = SimpleNamespace(matching_status=SimpleNamespace(matching=zenoh_says))
    publisher._host = SimpleNamespace(enqueue=lambda callback, *args: callback(*args))
    return publisher, heard


def test_a_recheck_tells_the_watchers_what_zenoh_says_when_they_were_told_otherwise():
    publisher, heard = watched(zenoh_says=True, told=False)
    publisher.recheck()
    assert heard == [True]


def test_a_recheck_says_nothing_when_the_watchers_know_already():
    publisher, heard = watched(zenoh_says=True, told=True)
    publisher.recheck()
    assert heard == []
