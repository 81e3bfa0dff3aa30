"""Matched events (PublisherEventCallbacks(matched=…), SubscriptionEventCallbacks(matched=…)):
the endpoints of the other kind on the same topic, counted from the graph's liveliness tokens
as they come and go, and handed to the callback on the node's executor as rclpy's
QoSPublisherMatchedInfo / QoSSubscriptionMatchedInfo (total and current counts, and their
changes since the last event)."""

from __future__ import annotations

import threading
from typing import Any

import zenoh

from launcher.bus import keys
from launcher.records import dataclass


@dataclass
class MatchedCounts:
    """How many endpoints match, in all and now, and the change since the last event."""
    total_count: int = 0
    total_count_change: int = 0
    current_count: int = 0
    current_count_change: int = 0


class QoSPublisherMatchedInfo(MatchedCounts):
    """A publisher's matched subscriptions."""


class QoSSubscriptionMatchedInfo(MatchedCounts):
    """A subscription's matched publishers."""


class MatchWatcher:
    """Watches the tokens of `kind` (keys.SUBSCRIPTION for a publisher, keys.PUBLISHER for a
    subscription) on `topic`; each change is one event."""

    def __init__(self, node: Any, topic: str, kind: str, callback: Any, info: type) -> None:
        self._node, self._callback, self._info = node, callback, info
        self._alive: set[str] = set()
        self._total = self._reported_total = self._reported_current = 0
        self._lock = threading.Lock()
        key = (f"{keys.ROS.liveliness}/{keys.DOMAIN}/*/*/*/{kind}/*/*/*/"
               f"{keys.mangle(topic)}/**")
        self._subscriber = node.handle.session.liveliness().declare_subscriber(
            key, zenoh.handlers.Callback(self._on_token, indirect=False), history=True)

    def _on_token(self, sample: Any) -> None:
        name = str(sample.key_expr)
        with self._lock:
            if sample.kind == zenoh.SampleKind.PUT:
                if name in self._alive:
                    return
                self._alive.add(name)
                self._total += 1
            elif name in self._alive:
                self._alive.discard(name)
            else:
                return
            current = len(self._alive)
            info = self._info(total_count=self._total,
                              total_count_change=self._total - self._reported_total,
                              current_count=current,
                              current_count_change=current - self._reported_current)
            self._reported_total, self._reported_current = self._total, current
        from rclpy.node import live_host

        host = live_host(self._node)
        if host is not None:
            host.enqueue(self._callback, info)

    def destroy(self) -> None:
        self._subscriber.undeclare()
