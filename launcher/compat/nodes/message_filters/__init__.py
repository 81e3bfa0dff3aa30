"""message_filters, as ROS 2's: a Subscriber as a filter, a Cache of the latest messages, and
synchronizers that hand a callback one message of each input with the same stamp
(TimeSynchronizer) or stamps within `slop` seconds (ApproximateTimeSynchronizer)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from rclpy.duration import Duration
from rclpy.time import Time


class SimpleFilter:
    """A stage of a filter chain: callbacks registered on it get what it passes on."""

    def __init__(self) -> None:
        self.callbacks: dict[int, tuple[Callable[..., Any], tuple]] = {}

    def registerCallback(self, cb: Callable[..., Any], *args: Any) -> int:  # noqa: N802
        """Call `cb(message…, *args)` for each message this filter passes on; returns the
        connection's key."""
        key = len(self.callbacks)
        self.callbacks[key] = (cb, args)
        return key

    def signalMessage(self, *msg: Any) -> None:  # noqa: N802
        """Pass `msg` (one message, or one of each input) on to every registered callback."""
        for cb, args in list(self.callbacks.values()):
            cb(*(msg + args))


class Subscriber(SimpleFilter):
    """A subscription whose messages go to the filters connected to it."""

    def __init__(self, node: Any, msg_type: Any, topic: str, qos_profile: Any = 10,
                 **kwargs: Any) -> None:
        super().__init__()
        self.node, self.topic = node, topic
        self.sub = node.create_subscription(msg_type, topic, self.callback, qos_profile,
                                            **kwargs)

    def callback(self, msg: Any) -> None:
        """The subscription's callback: the message goes on to the connected filters."""
        self.signalMessage(msg)

    def getTopic(self) -> str:  # noqa: N802
        """The subscribed topic's full name."""
        return self.sub.topic_name

    def __getattr__(self, key: str) -> Any:
        return getattr(self.sub, key)


def _stamp(msg: Any, allow_headerless: bool, clock: Any = None) -> Time:
    header = getattr(msg, "header", None)
    if header is None:
        if not allow_headerless:
            raise AttributeError(f"{type(msg).__name__} has no header: pass "
                                 "allow_headerless=True to stamp it with the time it came")
        from rclpy.clock import ROSClock

        return (clock or ROSClock()).now()
    return Time.from_msg(header.stamp)


class Cache(SimpleFilter):
    """The last `cache_size` messages of its input, ordered by stamp."""

    def __init__(self, f: SimpleFilter, cache_size: int = 1,
                 allow_headerless: bool = False) -> None:
        super().__init__()
        self.connectInput(f)
        self.cache_size, self.allow_headerless = cache_size, allow_headerless
        self.cache_msgs: list[Any] = []
        self.cache_times: list[Time] = []
        self.lock = threading.Lock()

    def connectInput(self, f: SimpleFilter) -> None:  # noqa: N802
        """Take messages from filter `f`."""
        self.incoming_connection = f.registerCallback(self.add)

    def add(self, msg: Any) -> None:
        """Keep `msg` in stamp order (the oldest dropped past `cache_size`) and pass it on."""
        stamp = _stamp(msg, self.allow_headerless)
        with self.lock:
            index = len(self.cache_times)
            while index and self.cache_times[index - 1] > stamp:
                index -= 1
            self.cache_times.insert(index, stamp)
            self.cache_msgs.insert(index, msg)
            while len(self.cache_msgs) > self.cache_size:
                del self.cache_msgs[0], self.cache_times[0]
        self.signalMessage(msg)

    # (compared by nanoseconds: a stamp's clock type is ROS time, a Time the user makes
    # is the system's, and rclpy refuses to compare those)
    def getInterval(self, from_stamp: Time, to_stamp: Time) -> list[Any]:  # noqa: N802
        """The cached messages stamped from `from_stamp` to `to_stamp`, both included."""
        low, high = from_stamp.nanoseconds, to_stamp.nanoseconds
        with self.lock:
            return [m for m, t in zip(self.cache_msgs, self.cache_times, strict=True)
                    if low <= t.nanoseconds <= high]

    def getElemAfterTime(self, stamp: Time) -> Any:  # noqa: N802
        """The first cached message stamped at or after `stamp`, or None."""
        with self.lock:
            return next((m for m, t in zip(self.cache_msgs, self.cache_times, strict=True)
                         if t.nanoseconds >= stamp.nanoseconds), None)

    def getElemBeforeTime(self, stamp: Time) -> Any:  # noqa: N802
        """The last cached message stamped at or before `stamp`, or None."""
        with self.lock:
            found = [m for m, t in zip(self.cache_msgs, self.cache_times, strict=True)
                     if t.nanoseconds <= stamp.nanoseconds]
        return found[-1] if found else None

    def getLastestTime(self) -> Time | None:  # noqa: N802 (ROS's spelling)
        """The newest cached stamp, or None (ROS's spelling)."""
        with self.lock:
            return self.cache_times[-1] if self.cache_times else None

    def getLatestTime(self) -> Time | None:  # noqa: N802
        """The newest cached stamp, or None."""
        return self.getLastestTime()

    def getOldestTime(self) -> Time | None:  # noqa: N802
        """The oldest cached stamp, or None."""
        with self.lock:
            return self.cache_times[0] if self.cache_times else None

    def getLast(self) -> Any:  # noqa: N802
        """The newest cached message, or None."""
        with self.lock:
            return self.cache_msgs[-1] if self.cache_msgs else None


class TimeSynchronizer(SimpleFilter):
    """One message of each input with exactly the same stamp; `queue_size` stamps kept."""

    def __init__(self, fs: list[SimpleFilter], queue_size: int) -> None:
        super().__init__()
        self.queue_size = queue_size
        self.lock = threading.Lock()
        self.connectInput(fs)

    def connectInput(self, fs: list[SimpleFilter]) -> None:  # noqa: N802
        """Take messages from the filters `fs`, one queue each."""
        self.queues: list[dict[int, Any]] = [{} for _ in fs]
        self.input_connections = [f.registerCallback(self.add, q, i)
                                  for i, (f, q) in enumerate(zip(fs, self.queues, strict=True))]

    def add(self, msg: Any, my_queue: dict[int, Any], my_queue_index: int | None = None
            ) -> None:
        """Queue `msg` from one input; when every input has one with its stamp, pass them on
        together (older ones are dropped)."""
        stamp = _stamp(msg, False).nanoseconds
        with self.lock:
            my_queue[stamp] = msg
            while len(my_queue) > self.queue_size:
                del my_queue[min(my_queue)]
            common = set.intersection(*(set(q) for q in self.queues))
            if not common:
                return
            when = max(common)
            chosen = [q[when] for q in self.queues]
            for q in self.queues:
                for old in [s for s in q if s <= when]:
                    del q[old]
        self.signalMessage(*chosen)


class ApproximateTimeSynchronizer(TimeSynchronizer):
    """One message of each input whose stamps lie within `slop` seconds of each other."""

    def __init__(self, fs: list[SimpleFilter], queue_size: int, slop: float,
                 allow_headerless: bool = False) -> None:
        self.slop = Duration(seconds=slop).nanoseconds
        self.allow_headerless = allow_headerless
        super().__init__(fs, queue_size)

    def add(self, msg: Any, my_queue: dict[int, Any], my_queue_index: int | None = None
            ) -> None:
        """Queue `msg` from one input; when every other input has one within `slop` of it,
        pass the nearest of each on together (older ones are dropped)."""
        stamp = _stamp(msg, self.allow_headerless).nanoseconds
        with self.lock:
            my_queue[stamp] = msg
            while len(my_queue) > self.queue_size:
                del my_queue[min(my_queue)]
            # the newest message's company: in each other input, the stamp nearest to it
            picks = []
            for q in self.queues:
                if q is my_queue:
                    picks.append(stamp)
                    continue
                near = [s for s in q if abs(s - stamp) <= self.slop]
                if not near:
                    return
                picks.append(min(near, key=lambda s: abs(s - stamp)))
            if max(picks) - min(picks) > self.slop:
                return
            chosen = [q[s] for q, s in zip(self.queues, picks, strict=True)]
            for q, s in zip(self.queues, picks, strict=True):
                for old in [t for t in q if t <= s]:
                    del q[old]
        self.signalMessage(*chosen)


__all__ = ["ApproximateTimeSynchronizer", "Cache", "SimpleFilter", "Subscriber",
           "TimeSynchronizer"]
