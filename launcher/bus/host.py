"""What a node's entities (publishers, subscriptions, services, clients) use of their node:
its session, its place on the graph, its executor's queue and its logger. The node makes one
Host and hands it to each entity it creates; an entity never calls back into the node (rclpy's
ownership: the node makes the handle and passes it in).
"""

from __future__ import annotations

import contextlib
import itertools
import queue
import threading
import time
from collections.abc import Callable
from typing import Any

import zenoh

from launcher.bus import keys
from launcher.bus.logging import Logger
from launcher.bus.session import NoRouter, is_client, open_session

_node_ids = itertools.count()


def direct(callback: Callable[..., Any]) -> Any:
    """`callback` run on the Zenoh thread that receives, not handed to a Python thread of its
    own (zenoh-python's default: one thread per subscriber, queryable and matching listener,
    and a hand-over per sample). For what comes rarely and only queues work (queries): a
    component container ran a thread per publisher and service (740 threads for 30 robots).
    Not for subscriptions: zenoh-python's thread takes a stream's samples in batches where
    each direct one takes the GIL (Twist 1 → 1: 25–39 k/s against 65 k/s), and a callback
    that publishes (a bridge's) must not hold up the thread that receives: under a flood both
    ends waited on each other. Not for matching listeners either: Zenoh runs those on its Net
    runtime, whose thread would wait there for the GIL (see Publisher's listener)."""
    return zenoh.handlers.Callback(callback, indirect=False)


def join_callback_threads(timeout: float = 1.0) -> None:
    """zenoh-python runs a Python callback on a thread of its own (named "… (pyo3-closure)"),
    a daemon when the thread that declared the entity is one (a component's, a launch's
    worker). One that is still leaving Zenoh's channel as the interpreter finalises is stopped
    inside Rust code, which aborts the process ("FATAL: exception not rethrown"). At exit,
    once the nodes are destroyed and their channels closed, they are given `timeout` to end."""
    deadline = time.monotonic() + timeout
    for thread in threading.enumerate():
        if thread.daemon and thread.name.endswith("(pyo3-closure)"):
            thread.join(max(0.0, deadline - time.monotonic()))


class Host:
    def __init__(self, session: zenoh.Session, namespace: str, name: str,
                 logger: Logger, space: keys.Space = keys.ROS) -> None:
        self.session, self.namespace, self.name, self.logger = session, namespace, name, logger
        self.space = space  # where its entities are, unless one says otherwise
        self._elsewhere: dict[keys.Space, Any] = {}  # its node token in the other space
        self.timeout = 2.0  # for queries made on the caller's behalf (latched samples)
        self.node_id = next(_node_ids)
        self._entity_ids = itertools.count(1)
        self._queue: queue.SimpleQueue[tuple[Callable[..., Any], tuple]] = queue.SimpleQueue()
        # The executor waits on this lock, not in SimpleQueue.get(timeout): that waits for ever
        # when a signal handler outlasts what was left of its timeout (CPython 3.11), and the
        # sim's loop waits in slices of a millisecond, so a Ctrl-C landing there went unseen.
        # A lock's timed acquire gives up instead. Released ("rung") after each put.
        self._bell = threading.Lock()
        self._bell.acquire()
        self.entities: list[Any] = []
        self.publisher_gids: set[bytes] = set()  # its publishers', to know its own samples
        self._graph_session: zenoh.Session | None = None

    def announce(self, kind: str, name: str = "", type_name: str = "", type_hash: str = "",
                 qos: str = "", space: keys.Space | None = None) -> Any:
        """The liveliness token of this node (kind NODE) or of one of its entities."""
        space = space or self.space
        if kind != keys.NODE and space != self.space and space not in self._elsewhere:
            self._elsewhere[space] = self.announce(keys.NODE, space=space)  # seen there too
        number = 0 if kind == keys.NODE else next(self._entity_ids)
        entity = keys.Entity(str(self.session.zid()), self.node_id, number, kind,
                             self.namespace, self.name, name, type_name, type_hash, qos)
        return self.session.liveliness().declare_token(
            keys.liveliness_key(keys.domain(), entity, space))

    def share_queue(self, other: Host) -> None:
        """Hand this host's callbacks to `other`'s executor: the two nodes are spun as one
        (the nodes a process runs on one thread, as the sim runs its controllers')."""
        self._queue, self._bell = other._queue, other._bell

    def ring_with(self, bell: threading.Lock) -> None:
        """Ring `bell` (held, released at each put) instead of the host's own: the executor of
        a client library that waits for the work of several nodes at once."""
        self._bell = bell

    def enqueue(self, callback: Callable[..., Any], *args: Any) -> None:
        """Work for the node's executor (spin), from any thread."""
        self._queue.put((callback, args))
        with contextlib.suppress(RuntimeError):  # rung already, by another thread
            if self._bell.locked():
                self._bell.release()

    def next_work(self, timeout: float | None) -> tuple[Callable[..., Any], tuple] | None:
        """The executor's next callback and its arguments, waiting up to `timeout` (None:
        until one comes); None if none came."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            try:
                return self._queue.get_nowait()
            except queue.Empty:
                pass
            if deadline is None:
                self._bell.acquire()
            else:
                left = deadline - time.monotonic()
                if left <= 0 or not self._bell.acquire(timeout=left):
                    return None

    def adopt(self, entity: Any) -> Any:
        self.entities.append(entity)
        return entity

    def forget(self, entity: Any) -> bool:
        """Drop an entity being destroyed; False if it already was (destroy is idempotent)."""
        if entity in self.entities:
            self.entities.remove(entity)
            return True
        return False

    def drop(self, entity: Any, *declared: Any) -> None:
        """Forget an entity being destroyed and undeclare what it declared (once)."""
        if self.forget(entity):
            for item in declared:
                item.undeclare()

    def graph_session(self) -> zenoh.Session:
        """The session to ask who is on the bus: the router answers a client with every
        token (a node's own session is one). A peer's liveliness query reaches only the peers
        it has links to, and with dozens of nodes starting at once some links come late or
        not at all (ten robots' `create`s never saw the sim): a peer's node (one given a
        session of its own) asks through a client of its own, opened at the first
        question."""
        if self._graph_session is None:
            self._graph_session = self.session
            if is_client(self.session):
                return self.session
            with contextlib.suppress(NoRouter):
                self._graph_session = open_session("client")
        return self._graph_session

    def close_graph_session(self) -> None:
        if self._graph_session not in (None, self.session):
            with contextlib.suppress(zenoh.ZError):
                self._graph_session.close()  # type: ignore[union-attr]
