"""topic_tools' relay, throttle, drop and mux, as ROS 2's: each takes an input topic's
messages (their type found on the graph, the bytes passed on untouched) to an output topic.

    relay IN [OUT]                              (OUT: IN_relay)
    throttle messages IN RATE [OUT]             (at most RATE messages a second; OUT: IN_throttle)
    throttle bytes IN BYTES_PER_SEC WINDOW [OUT]
    drop IN X Y [OUT]                           (drops X of every Y; OUT: IN_drop)
    mux OUT IN1 [IN2 …]                         (~/select picks the input, "__none" none)
"""

from __future__ import annotations

import sys
import time
from collections import deque
from collections.abc import Callable
from typing import Any

from launcher.bus import graph
from launcher.bus.node import Node
from launcher.errors import LaunchError, UsageError
from launcher.nodes import running

TYPE_WAIT = 30.0  # s: how long an input's type is waited for (its publisher may come later)


def _type_of(node: Node, topic: str) -> str:
    """The type published on `topic`, waiting for a publisher."""
    name = node.resolve(topic)
    deadline = time.monotonic() + TYPE_WAIT
    while time.monotonic() < deadline:
        info = graph.topics(node.graph_session()).get(name)
        if info is not None and info.publishers:
            return sorted({p.type_name for p in info.publishers})[0]
        time.sleep(0.2)
    raise LaunchError(f"no publisher of {name} appeared within {TYPE_WAIT:g} s: its type is "
                      "what the output is published as")


def _forward(node: Node, source: str, target: str, keep: Callable[[bytes], bool]) -> None:
    type_name = _type_of(node, source)
    out = node.create_publisher(type_name, target)

    def on_payload(payload: bytes) -> None:
        if keep(payload):
            out.publish_raw(payload)
    node.create_subscription(type_name, source, on_payload, raw=True, inline=True)


def _words(node: Node, usage: str, low: int, high: int) -> list[str]:
    words = [w for w in node.args]
    if not low <= len(words) <= high:
        raise UsageError(f"usage: {usage}")
    return words


def relay(node: Node) -> None:
    words = _words(node, "relay IN [OUT]", 1, 2)
    _forward(node, words[0], words[1] if len(words) > 1 else f"{words[0]}_relay",
             lambda _: True)


def throttle(node: Node) -> None:
    usage = "throttle messages IN RATE [OUT] | throttle bytes IN BYTES_PER_SEC WINDOW [OUT]"
    words = list(node.args)
    if not words or words[0] not in ("messages", "bytes"):
        raise UsageError(f"usage: {usage}")
    try:
        if words[0] == "messages" and len(words) in (3, 4):
            period = 1.0 / float(words[2])
            last = [-float("inf")]

            def keep(_: bytes) -> bool:
                now = time.monotonic()
                if now - last[0] >= period:
                    last[0] = now
                    return True
                return False
            target = words[3] if len(words) == 4 else f"{words[1]}_throttle"
        elif words[0] == "bytes" and len(words) in (4, 5):
            budget, window = float(words[2]), float(words[3])
            sent: deque[tuple[float, int]] = deque()

            def keep(payload: bytes) -> bool:
                now = time.monotonic()
                while sent and now - sent[0][0] > window:
                    sent.popleft()
                if sum(n for _, n in sent) + len(payload) > budget * window:
                    return False
                sent.append((now, len(payload)))
                return True
            target = words[4] if len(words) == 5 else f"{words[1]}_throttle"
        else:
            raise UsageError(f"usage: {usage}")
    except (ValueError, ZeroDivisionError):
        raise UsageError(f"the rate is a number above 0\nusage: {usage}") from None
    _forward(node, words[1], target, keep)


def drop(node: Node) -> None:
    words = _words(node, "drop IN X Y [OUT]", 3, 4)
    try:
        x, y = int(words[1]), int(words[2])
    except ValueError:
        raise UsageError("usage: drop IN X Y [OUT] (X of every Y messages are dropped)") \
            from None
    if not 0 <= x < y:
        raise UsageError(f"drop {x} of every {y}: X must be at least 0 and below Y")
    count = [0]

    def keep(_: bytes) -> bool:  # the first X of each Y go
        index, count[0] = count[0] % y, count[0] + 1
        return index >= x
    _forward(node, words[0], words[3] if len(words) == 4 else f"{words[0]}_drop", keep)


def mux(node: Node) -> None:
    words = _words(node, "mux OUT IN1 [IN2 …]", 2, 1000)
    target, inputs = words[0], words[1:]
    selected = [node.resolve(inputs[0])]
    types = {node.resolve(t): _type_of(node, t) for t in inputs}
    out = node.create_publisher(next(iter(types.values())), target)
    for topic, type_name in types.items():
        def on_payload(payload: bytes, topic: str = topic) -> None:
            if selected[0] == topic:
                out.publish_raw(payload)
        node.create_subscription(type_name, topic, on_payload, raw=True, inline=True)

    def select(request: Any, response: Any) -> Any:
        wanted = request.topic if request.topic == "__none" else node.resolve(request.topic)
        response.prev_topic = selected[0]
        if wanted != "__none" and wanted not in types:
            node.get_logger().warning(f"mux: '{request.topic}' is not an input "
                                      f"(inputs: {', '.join(types)})")
            response.success = False
            return response
        selected[0] = wanted
        response.success = True
        return response
    node.create_service("topic_tools_interfaces/srv/MuxSelect", "~/select", select)

    def listing(request: Any, response: Any) -> Any:
        response.topics = list(types)
        return response
    node.create_service("topic_tools_interfaces/srv/MuxList", "~/list", listing)


def relay_main() -> int:
    return running.run_node("relay", relay)


def throttle_main() -> int:
    return running.run_node("throttle", throttle)


def drop_main() -> int:
    return running.run_node("drop", drop)


def mux_main() -> int:
    return running.run_node("mux", mux)


if __name__ == "__main__":
    sys.exit(relay_main())
