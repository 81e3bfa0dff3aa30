"""A publisher's watchers (lazy nodes) are told when subscribers come or all go; a word Zenoh
never sent, or one that came out of order, heals at the node's next recheck; an endpoint's
matches are counted from the graph's tokens (the bus faked)."""

from __future__ import annotations

import threading
from types import SimpleNamespace

import zenoh

from launcher.bus import keys
from launcher.bus.matching import MatchedStatus, MatchWatch
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


def test_matches_are_counted_from_the_graphs_tokens_as_rmw_counts_them():
    """rclpy's matched events: each token of the other side that comes or goes is one status,
    with the counts in all and now and their changes; a token told twice counts once."""
    asked: list = []

    def declare_subscriber(selector, handler, history):
        asked.append((selector, history))
        return SimpleNamespace(undeclare=lambda: None)

    session = SimpleNamespace(liveliness=lambda: SimpleNamespace(
        declare_subscriber=declare_subscriber))
    told: list[MatchedStatus] = []
    watch = MatchWatch(session, "/r1/chatter", keys.SUBSCRIPTION, told.append)
    assert asked == [(f"@ros2_lv/{keys.domain()}/*/*/*/MS/*/*/*/%r1%chatter/**", True)]
    came, went = zenoh.SampleKind.PUT, zenoh.SampleKind.DELETE
    for kind, token in [(came, "a"), (came, "a"), (came, "b"), (went, "a"), (went, "c"),
                        (came, "a")]:
        watch._on_token(SimpleNamespace(key_expr=token, kind=kind))
    assert [(s.total_count, s.total_count_change, s.current_count, s.current_count_change)
            for s in told] == [(1, 1, 1, 1), (2, 1, 2, 1), (2, 0, 1, -1), (3, 1, 2, 1)]
