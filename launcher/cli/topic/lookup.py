"""A topic named on the command line: its full name, and its type from the graph."""

from __future__ import annotations

import time
from typing import Any

from launcher.bus import graph, keys
from launcher.bus.names import expand
from launcher.errors import LaunchError, did_you_mean


def topic_name(name: str) -> str:
    return expand(name)


def type_of(session: Any, topic: str, given: str | None,
            space: keys.Space = keys.ROS) -> str:
    if given:
        return given
    deadline = time.monotonic() + 5.0
    while True:
        table = graph.topics(session, space)
        info = table.get(topic)
        if info and info.publishers:
            return sorted(info.types)[0]
        if time.monotonic() > deadline:
            if info:  # subscribed to, never published: its own name is no suggestion
                hint = f" (it has {len(info.subscribers)} subscriber(s))"
            else:
                hint = did_you_mean(topic, (t for t, i in table.items() if i.publishers))
            raise LaunchError(f"nobody publishes '{topic}'{hint}; give its type to wait for "
                              "it: launcher topic echo TOPIC TYPE")
        time.sleep(0.1)
