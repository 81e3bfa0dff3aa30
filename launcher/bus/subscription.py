"""A subscription: samples on its topic's key delivered to the node's executor (or inline, on
Zenoh's thread, when asked). A transient local one fetches what latched publishers hold when it
starts, and again whenever a publisher of its topic appears (its liveliness token), until that
fetch brings something or a backoff of about half a minute runs out: a latched message
published once, while the routes between new nodes are still forming (or while a loaded
machine delays the publisher's first message), is not lost (what rmw_zenoh's advanced
subscriber does with its late-publisher detection). A malformed payload is dropped with one
warning per topic."""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Callable
from typing import Any

import zenoh

from launcher.bus import keys
from launcher.bus.host import Host
from launcher.bus.qos import QoS
from launcher.bus.types import registry

REFETCH_AFTER = (0.05, 0.2, 0.5, 1.0, 2.0, 4.0, 8.0, 15.0)  # s between fetches, for a new
# publisher, until one brings something


class Subscription:
    def __init__(self, host: Host, type_name: str, topic: str, callback: Callable[[Any], None],
                 qos: QoS, raw: bool = False, inline: bool = False,
                 remote_only: bool = False) -> None:
        types = registry()
        self.type_name = types.ensure(type_name)
        self.topic, self.qos, self._host, self._callback = topic, qos, host, callback
        self._raw, self._inline = raw, inline
        key = keys.topic_key(keys.DOMAIN, topic, self.type_name, types.type_hash(self.type_name))
        self._subscriber = host.session.declare_subscriber(
            key, self._on_sample,
            allowed_origin=zenoh.Locality.REMOTE if remote_only else zenoh.Locality.ANY)
        self._token = host.announce(keys.SUBSCRIPTION, topic, self.type_name,
                                    types.type_hash(self.type_name), qos.key())
        self._warned = False
        self._key, self._closed = key, False
        self._watch: Any = None
        if qos.transient_local:  # fetch what latched publishers hold, now and as they come
            self._watch = host.session.liveliness().declare_subscriber(
                keys.publishers_key(keys.DOMAIN, topic, self.type_name), self._on_publisher)
            self.fetch()

    def fetch(self) -> int:
        """Ask the latched publishers of the topic for what they hold; how many answered."""
        found = 0
        if self._closed:
            return found
        with contextlib.suppress(zenoh.ZError):
            for reply in self._host.session.get(self._key, timeout=self._host.timeout):
                if reply.ok is not None:
                    found += 1
                    self._on_sample(reply.ok)
        return found

    def _on_publisher(self, sample: zenoh.Sample) -> None:
        if sample.kind == zenoh.SampleKind.PUT:
            self._refetch(0)

    def _refetch(self, attempt: int) -> None:
        """Fetch after the attempt's delay; again, later, while nothing comes back."""
        def run() -> None:
            if not self.fetch() and attempt + 1 < len(REFETCH_AFTER):
                self._refetch(attempt + 1)

        timer = threading.Timer(REFETCH_AFTER[attempt], run)
        timer.daemon = True
        timer.start()

    def _on_sample(self, sample: zenoh.Sample) -> None:
        if self._inline:
            self._deliver(sample.payload.to_bytes())
        else:
            self._host.enqueue(self._deliver, sample.payload.to_bytes())

    def _deliver(self, payload: bytes) -> None:
        if self._raw:
            self._callback(payload)
            return
        try:
            message = registry().deserialize(payload, self.type_name)
        except Exception as exc:  # malformed payload: dropped, said once per topic
            if not self._warned:
                self._warned = True
                self._host.logger.warning(
                    f"dropped a malformed {self.type_name} message on {self.topic}: {exc}")
            return
        self._callback(message)

    def destroy(self) -> None:
        if not self._host.forget(self):
            return
        self._closed = True
        if self._watch is not None:
            self._watch.undeclare()
        self._subscriber.undeclare()
        self._token.undeclare()
