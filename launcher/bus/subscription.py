"""A subscription: samples on its topic's key delivered to the node's executor (or inline, on
Zenoh's thread, when asked). A transient local one is what rmw_zenoh makes of it: zenoh-ext's
advanced subscriber, which asks every latched (advanced) publisher for what it holds, at the
start and whenever one appears later, and, when reliable, recovers a message it missed from
the publisher's heartbeat. A malformed payload is dropped with one warning per topic.

Samples wait for the executor in a queue of the subscription's own, `depth` deep (KEEP_LAST, as
in ROS 2): when the node cannot keep up, the oldest are dropped, so a flood on one topic costs
bounded memory, and the executor's queue holds one turn per subscription, not one per sample,
so other callbacks (and the sim's physics) still get theirs."""

from __future__ import annotations

import functools
import threading
from collections import deque
from collections.abc import Callable
from typing import Any

import zenoh
import zenoh.ext

from launcher.bus import keys
from launcher.bus.host import Host
from launcher.bus.lockstep import LEDGER
from launcher.bus.matching import MatchedStatus, MatchWatch
from launcher.bus.qos import QoS
from launcher.bus.types import registry


class Subscription:
    def __init__(self, host: Host, type_name: str, topic: str, callback: Callable[[Any], None],
                 qos: QoS, raw: bool = False, inline: bool = False,
                 remote_only: bool = False, space: keys.Space | None = None,
                 make: Callable[[str, list[Any]], Any] | None = None) -> None:
        types = registry()
        self.type_name = types.ensure(type_name)
        self.topic, self.qos, self._host, self._callback = topic, qos, host, callback
        self._raw, self._inline = raw, inline
        self._read = None if raw else types.reader(self.type_name, make)
        # (before declaring: a transient local subscriber gets history samples at once)
        self._pending: deque[bytes] = deque(maxlen=max(qos.depth, 1))
        self._lock = threading.Lock()
        self._turn_queued = False
        self._warned = False
        self.space = space or host.space
        self.key = key = keys.topic_key(keys.domain(), topic, self.type_name,
                                        types.type_hash(self.type_name), self.space)
        LEDGER.subscribe(key)
        # its node's own samples are told by their publisher's gid (the attachment's last 16
        # bytes), not by Zenoh's locality: in a component container, nodes share a session
        self._own = host.publisher_gids if remote_only else None
        if qos.transient_local:
            self._subscriber: Any = zenoh.ext.declare_advanced_subscriber(
                host.session, key, self._on_sample,  # zenoh-python's thread: see host.direct
                history=zenoh.ext.HistoryConfig(detect_late_publishers=True,
                                                max_samples=qos.depth),
                recovery=zenoh.ext.RecoveryConfig(periodic_queries=None, heartbeat=True)
                if qos.reliable else None,
                subscriber_detection=True)
        else:
            self._subscriber = host.session.declare_subscriber(key, self._on_sample)
        self._token = host.announce(keys.SUBSCRIPTION, topic, self.type_name,
                                    types.type_hash(self.type_name), qos.key(), self.space)
        self._matches: list[MatchWatch] = []

    def watch_matches(self, callback: Callable[[MatchedStatus], None]) -> None:
        """Call `callback(status)` on the executor each time a publisher on the graph matches
        or leaves (those there already at once), until the subscription is destroyed: the
        counts of rclpy's matched events (bus/matching.py)."""
        self._matches.append(MatchWatch(self._host.session, self.topic, keys.PUBLISHER,
                                        functools.partial(self._host.enqueue, callback),
                                        self.space))

    def _on_sample(self, sample: zenoh.Sample) -> None:
        if self._own is not None:
            attachment = sample.attachment
            if attachment is not None and attachment.to_bytes()[-16:] in self._own:
                return
        payload = sample.payload.to_bytes()
        if self._inline:
            self._deliver(payload)
        else:
            with self._lock:
                self._pending.append(payload)  # full: the oldest goes (KEEP_LAST)
                queue_turn = not self._turn_queued
                self._turn_queued = True
            if queue_turn:
                self._host.enqueue(self._take)
        if LEDGER.enabled:  # (a lockstep waits here: what has come, once it is handled)
            LEDGER.note(sample.attachment)

    def _take(self) -> None:
        """The executor's turn: deliver the oldest waiting sample; queue another turn if more
        are waiting (behind whatever else is queued)."""
        with self._lock:
            if not self._pending:
                self._turn_queued = False
                return
            payload = self._pending.popleft()
            more = bool(self._pending)
            self._turn_queued = more
        if more:
            self._host.enqueue(self._take)
        self._deliver(payload)

    def _deliver(self, payload: bytes) -> None:
        if self._raw:
            self._callback(payload)
            return
        try:
            message = self._read(payload)
        except Exception as exc:  # malformed payload: dropped, said once per topic
            if not self._warned:
                self._warned = True
                self._host.logger.warning(
                    f"dropped a malformed {self.type_name} message on {self.topic}: {exc}")
            return
        self._callback(message)

    def destroy(self) -> None:
        if self._host.forget(self):
            LEDGER.unsubscribe(self.key)
            for item in (*self._matches, self._subscriber, self._token):
                item.undeclare()


class FirstMessage:
    """A subscription's callback that keeps the first message it is given (the waits for
    one message that rclpy's and rospy's wait_for_message are)."""

    def __init__(self) -> None:
        self.message: Any = None
        self._arrived = threading.Event()

    def __call__(self, message: Any) -> None:
        if not self._arrived.is_set():
            self.message = message
            self._arrived.set()

    def wait(self, timeout: float) -> bool:
        """Whether the message has come, waiting up to `timeout` seconds for it."""
        return self._arrived.wait(timeout)
