"""A publisher: CDR payloads put on its topic's key with rmw_zenoh's attachment. A transient
local one is what rmw_zenoh makes of it: zenoh-ext's advanced publisher, keeping its last
`depth` messages for late subscribers, detectable by them (`<key>/@adv/pub/…`), and with
sporadic heartbeats when reliable, so that a subscriber can tell it missed one."""

from __future__ import annotations

import functools
import itertools
import os
import threading
import time
from collections.abc import Callable
from typing import Any

import zenoh
import zenoh.ext

from launcher.bus import keys
from launcher.bus.host import Host
from launcher.bus.matching import MatchedStatus, MatchWatch
from launcher.bus.qos import KEEP_ALL_DEPTH, QoS
from launcher.bus.types import registry

HEARTBEAT = 0.5  # s, a reliable latched publisher's sporadic heartbeat (rmw_zenoh's period)


class Publisher:
    def __init__(self, host: Host, type_name: str, topic: str, qos: QoS,
                 space: keys.Space | None = None) -> None:
        types = registry()
        self.type_name = types.ensure(type_name)
        self.topic, self.qos, self._host = topic, qos, host
        self.space = space or host.space
        self.key = key = keys.topic_key(keys.domain(), topic, self.type_name,
                                        types.type_hash(self.type_name), self.space)
        # As rmw_zenoh: only a reliable keep-all publisher blocks under congestion; the others
        # drop what a congested link cannot take, so a subscriber that stops reading (a
        # stopped process, a slow link) never stalls the publisher, nor the router's other
        # links behind it (the sim's sensors, its clock).
        blocking = qos.reliable and qos.depth == KEEP_ALL_DEPTH
        options: dict[str, Any] = {
            "reliability": zenoh.Reliability.RELIABLE if qos.reliable else
            zenoh.Reliability.BEST_EFFORT,
            "congestion_control": zenoh.CongestionControl.BLOCK if blocking else
            zenoh.CongestionControl.DROP}
        # Whether anyone listens (a plain publisher tells, an advanced one does not).
        self._publisher = host.session.declare_publisher(key, **options)
        self._latched: Any = None
        if qos.transient_local:
            self._latched = zenoh.ext.declare_advanced_publisher(
                host.session, key, **options, publisher_detection=True,
                cache=zenoh.ext.CacheConfig(qos.depth),
                sample_miss_detection=zenoh.ext.MissDetectionConfig(
                    heartbeat=None, sporadic_heartbeat=HEARTBEAT) if qos.reliable else None)
        self._sequence = itertools.count(1)
        self.sent = 0  # the sequence number of the last sample sent to a subscriber (lockstep)
        self.gid = os.urandom(16)
        host.publisher_gids.add(self.gid)
        self._write = types.writer(self.type_name)
        self._token = host.announce(keys.PUBLISHER, topic, self.type_name,
                                    types.type_hash(self.type_name), qos.key(), self.space)
        self._watchers: list[Callable[[bool], None]] = []
        self._told = False  # what the watchers were last told
        self._watching = threading.Lock()  # (not _lock: destroy() holds that while the
        self._closed = False               # listener's undeclare waits for its callback)
        self._lock = threading.Lock()
        # Declared only once something watches, its callback on a thread of zenoh-python's:
        # one run on Zenoh's own thread (the Net runtime's) waits there for the GIL, while
        # the thread holding it may be undeclaring an advanced publisher, whose heartbeat
        # task needs that runtime to end (zenoh-python stops it holding the GIL): the
        # process hung, a container of robots past SIGINT and SIGTERM.
        self._listener: Any = None
        self._matches: list[MatchWatch] = []

    @property
    def _matching(self) -> bool:
        """Whether any subscriber matches: Zenoh keeps it current, so asking costs a fraction
        of a microsecond (the sim asks every step)."""
        return self._publisher.matching_status.matching

    def _on_matching(self, status: Any) -> None:
        with self._watching:  # (queued in the order told: see watch_subscribers)
            if status.matching == self._told:
                return
            self._told = status.matching
            for watcher in self._watchers:
                self._host.enqueue(watcher, status.matching)

    def watch_subscribers(self, callback: Callable[[bool], None]) -> None:
        """Call `callback(matching)` on the executor whenever subscribers come or all go
        (and once now); lazy bridges subscribe to their source only while someone listens.
        What a watcher is told is queued under the lock that `_told` is kept under: a change
        told on Zenoh's thread while the first word was on its way came before it, and the
        watcher was left with the older word for good (a robot_state_publisher that never
        published tf)."""
        with self._watching:
            if self._listener is None:
                self._listener = self._publisher.declare_matching_listener(self._on_matching)
            self._told = matching = self._matching
            self._watchers.append(callback)
            self._host.enqueue(callback, matching)

    def watch_matches(self, callback: Callable[[MatchedStatus], None]) -> None:
        """Call `callback(status)` on the executor each time a subscription on the graph
        matches or leaves (those there already at once), until the publisher is destroyed:
        the counts of rclpy's matched events (bus/matching.py)."""
        self._matches.append(MatchWatch(self._host.session, self.topic, keys.SUBSCRIPTION,
                                        functools.partial(self._host.enqueue, callback),
                                        self.space))

    def recheck(self) -> bool:
        """Tell the watchers what Zenoh says now where it differs from what they were told
        (Node.watch_subscribers calls this on a timer); False once destroyed (no more to
        look at)."""
        with self._watching:
            if self._closed or not self._watchers:
                return not self._closed
            matching = self._matching
            if matching == self._told:
                return True
            self._told = matching
            for watcher in self._watchers:
                self._host.enqueue(watcher, matching)
            return True

    def publish(self, message: Any) -> None:
        self.publish_raw(self._write(message))

    def publish_raw(self, payload: bytes) -> None:
        """Publish a CDR payload as it is (bag play, bridges)."""
        with self._lock:  # a callback on Zenoh's thread may race destroy() (a bridge's)
            if self._closed:
                return
            sequence = next(self._sequence)
            if self._matching:  # (one that nobody was there to hear is not waited for)
                self.sent = sequence
            attachment = keys.attachment(sequence, time.time_ns(), self.gid)
            (self._latched or self._publisher).put(payload, attachment=attachment)

    def get_subscription_count(self) -> int:
        """1 while any subscriber matches (Zenoh does not count them), else 0."""
        return 0 if self._closed or not self._matching else 1

    def destroy(self) -> None:
        if not self._host.forget(self):
            return
        with self._lock:  # never while a put is under way: Zenoh says "Already borrowed"
            self._closed = True
            for item in (*self._matches, self._listener, self._latched, self._publisher,
                         self._token):
                if item is not None:
                    item.undeclare()
