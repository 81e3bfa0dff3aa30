"""Matched events (PublisherEventCallbacks(matched=…), SubscriptionEventCallbacks(matched=…)):
the bus counts an endpoint's matches on the graph (launcher/bus/matching.py, rmw's matched
status: total and current counts, and their changes since the last event); each change reaches
the callback on the node's executor as rclpy's QoSPublisherMatchedInfo /
QoSSubscriptionMatchedInfo."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from launcher.bus.matching import MatchedStatus
from launcher.records import dataclass


@dataclass
class StatusCounts:
    """An rmw event status's counts: in all, and the change since the last event (the event
    infos of rclpy.event_handler are these, some with more)."""
    total_count: int = 0
    total_count_change: int = 0


@dataclass
class MatchedCounts(StatusCounts):
    """How many endpoints match, in all and now, and the change since the last event."""
    current_count: int = 0
    current_count_change: int = 0


class QoSPublisherMatchedInfo(MatchedCounts):
    """A publisher's matched subscriptions."""


class QoSSubscriptionMatchedInfo(MatchedCounts):
    """A subscription's matched publishers."""


def watch(endpoint: Any, info: type[MatchedCounts], callback: Callable[[Any], Any]) -> None:
    """`callback(info)` on the executor at each change of the bus endpoint's matches."""
    def told(status: MatchedStatus) -> None:
        callback(info(total_count=status.total_count,
                      total_count_change=status.total_count_change,
                      current_count=status.current_count,
                      current_count_change=status.current_count_change))
    endpoint.watch_matches(told)
