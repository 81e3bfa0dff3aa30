"""Who matches an endpoint on the graph: the other side of its topic (a publisher's
subscriptions, a subscription's publishers), counted from the graph's liveliness tokens as they
come and go, as rmw counts a matched status: every one that ever matched, those that match
now, and the changes of both since the last report."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

import zenoh

from launcher.bus import keys
from launcher.records import dataclass


@dataclass(frozen=True)
class MatchedStatus:
    """rmw_matched_status_t: the matches in all and now, and their changes since the last
    status."""

    total_count: int
    total_count_change: int
    current_count: int
    current_count_change: int


class MatchWatch:
    """Watches the tokens of `kind` (keys.SUBSCRIPTION for a publisher, keys.PUBLISHER for a
    subscription) on `topic`: each one that comes or goes is one status, handed to `report` on
    Zenoh's thread in the order the changes came (those already there come first, at once)."""

    def __init__(self, session: zenoh.Session, topic: str, kind: str,
                 report: Callable[[MatchedStatus], None], space: keys.Space = keys.ROS) -> None:
        self._report = report
        self._alive: set[str] = set()
        self._total = 0
        self._lock = threading.Lock()  # (the changes are counted and reported in their order)
        self._subscriber = session.liveliness().declare_subscriber(
            keys.endpoints_selector(keys.domain(), kind, topic, space),
            zenoh.handlers.Callback(self._on_token, indirect=False), history=True)

    def _on_token(self, sample: Any) -> None:
        name = str(sample.key_expr)
        with self._lock:
            came = sample.kind == zenoh.SampleKind.PUT
            if came == (name in self._alive):  # (a token told twice, or one never seen)
                return
            if came:
                self._alive.add(name)
                self._total += 1
            else:
                self._alive.discard(name)
            # each status is one endpoint's coming (+1 to both counts) or going (-1 now)
            self._report(MatchedStatus(self._total, int(came), len(self._alive),
                                       1 if came else -1))

    def undeclare(self) -> None:
        self._subscriber.undeclare()
