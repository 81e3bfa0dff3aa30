"""rviz2, as launch files start it (`Node(package='rviz2', executable='rviz2',
arguments=['-d', cfg])`, `rviz:=true` in ros_gz demos): the view is Foxglove's.

It converts the `-d` config into a Foxglove layout (layout.py), written to
~/.launcher/layouts/<config>.json; starts the foxglove bridge for this graph unless one runs
(it stops with rviz2); prints the address Foxglove connects to and the layout to import;
then stays, as rviz2 does, until stopped. A real rviz2 (on PATH, or in an AMENT_PREFIX_PATH
install) is run instead, with the same arguments.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, UsageError, reported

NAME = "rviz2"
OWN_FILES = Path(__file__).resolve().parents[2]  # launcher's own files: not a real rviz2
BRIDGE_WAIT = 2.0  # s: a bridge starting beside rviz2 (the same launch) is waited for
URL_WAIT = 60.0  # s for a started bridge to say where it listens
DEFAULT_CONFIG = {"Visualization Manager": {
    "Global Options": {"Fixed Frame": "map"},
    "Displays": [{"Class": "rviz_default_plugins/Grid", "Name": "Grid", "Enabled": True}]}}


def main() -> int:
    return reported(lambda: _run("rviz2"), NAME)


def rviz_main() -> int:
    """ROS 1's `rviz` (`<node pkg="rviz" type="rviz" args="-d …"/>`): the same."""
    return reported(lambda: _run("rviz"), "rviz")


def _run(tool: str) -> int:
    from launcher.bus import ros_args

    words = ros_args.parse(sys.argv[1:]).user_args
    real = _real_tool(tool)
    if real is not None:
        os.execv(real, [real, *sys.argv[1:]])
    config, fixed = _options(words)
    from launcher.nodes.rviz import layout

    document = layout.read(config) if config else DEFAULT_CONFIG
    made, unmapped = layout.convert(document)
    if fixed:
        next(iter(made["configById"].values()))["followTf"] = fixed
    target = Path.home() / ".launcher" / "layouts" / f"{config.stem if config else 'default'}.json"
    layout.write(made, target)

    from launcher.bus.node import Node

    node = Node(NAME)
    bridge = None
    try:
        url = _running_bridge(node)
        if url is None:
            bridge, url = _start_bridge()
        say = node.get_logger().info
        panels = ", ".join(key.split("!")[0] for key in made["configById"])
        print(f"[{NAME}] rviz2's view is Foxglove's: connect Foxglove (the app, or "
              f"app.foxglove.dev) to {url}", file=sys.stderr, flush=True)
        print(f"[{NAME}] and import the layout {target} (Layouts → Import from file): "
              f"{panels} from {config or 'the default config'}", file=sys.stderr, flush=True)
        if unmapped:
            say(f"displays Foxglove's panels do not show: {', '.join(unmapped)}")
        node.spin()
    finally:
        node.destroy_node()
        if bridge is not None and bridge.poll() is None:
            bridge.send_signal(signal.SIGINT)
            try:
                bridge.wait(10)
            except subprocess.TimeoutExpired:
                bridge.kill()
    return 0


def _options(words: list[str]) -> tuple[Path | None, str | None]:
    """rviz2's own options: -d/--display-config, -f/--fixed-frame; the window's are taken."""
    config = fixed = None
    index = 0
    while index < len(words):
        word = words[index]
        if word in ("-d", "--display-config", "-f", "--fixed-frame", "-s", "--splash-screen"):
            if index + 1 >= len(words):
                raise UsageError(f"rviz2: {word} needs a value")
            value = words[index + 1]
            if word in ("-d", "--display-config"):
                config = Path(value)
            elif word in ("-f", "--fixed-frame"):
                fixed = value
            index += 2
            continue
        if word.startswith("--display-config="):
            config = Path(word.split("=", 1)[1])
        elif word not in ("-l", "--ogre-log", "--fullscreen", "--enable-transparency"):
            raise UsageError(f"rviz2: unknown option '{word}' (rviz2 takes -d CONFIG, "
                             "-f FRAME, -s SPLASH, -l, --fullscreen)")
        index += 1
    if config is not None and not config.is_file():
        raise LaunchError(f"rviz2: the display config {config} does not exist")
    return config, fixed


def _real_tool(tool: str) -> str | None:
    """A real rviz2 (or ROS 1's rviz): on PATH (not one of launcher's own commands), or in an
    install (AMENT_PREFIX_PATH, CMAKE_PREFIX_PATH for ROS 1)."""
    found = shutil.which(tool)
    if found and not Path(found).resolve().is_relative_to(OWN_FILES):
        return found
    prefixes = os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) + \
        os.environ.get("CMAKE_PREFIX_PATH", "").split(os.pathsep)
    for prefix in prefixes:
        candidate = Path(prefix) / "lib" / tool / tool if prefix else None
        if candidate is not None and os.access(candidate, os.X_OK):
            return str(candidate)
    return None


def _running_bridge(node: Any) -> str | None:
    """The address of a foxglove bridge on this graph (waited for a moment: one may be
    starting in the same launch), or None."""
    from launcher.bus import graph, listen_token

    deadline = time.monotonic() + BRIDGE_WAIT
    while True:
        found = [e.node_fqn for e in graph.nodes(node.graph_session())
                 if e.node == "foxglove_bridge"]
        if found or time.monotonic() > deadline:
            break
        time.sleep(0.2)
    if not found:
        return None
    getter = node.create_client("rcl_interfaces/srv/GetParameters",
                                f"{found[0]}/get_parameters")
    try:
        answer = getter.call(node.message("rcl_interfaces/srv/GetParameters_Request",
                                          names=["port", "address", "token"]), 5.0)
    finally:
        getter.destroy()
    from launcher.bus.parameters import from_message

    port, address, token = (from_message(v) for v in answer.values)
    host = f"[{address}]" if ":" in str(address) else address
    return listen_token.url(f"ws://{host}:{port}/", listen_token.load()
                            if token is not False and not listen_token.off() else None)


def _start_bridge() -> tuple[subprocess.Popen[str], str]:
    """A foxglove bridge of rviz2's own (it ends with rviz2, by the kernel's word if rviz2
    is killed), and its address."""
    import ctypes

    def die_with_parent() -> None:
        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM, 0, 0, 0)  # PDEATHSIG

    bridge = subprocess.Popen([sys.executable, "-m", "launcher", "run", "foxglove_bridge",
                               "foxglove_bridge"], stdin=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True, preexec_fn=die_with_parent,
                              start_new_session=True)  # (signalled by rviz2 alone, once)
    found: list[str] = []
    ready = threading.Event()

    def relay() -> None:
        assert bridge.stderr is not None
        for line in bridge.stderr:
            match = re.search(r"Foxglove connects to (\S+)", line)
            if match and not found:
                found.append(match.group(1))
                ready.set()
                continue
            sys.stderr.write(line)
        ready.set()

    threading.Thread(target=relay, daemon=True).start()
    ready.wait(URL_WAIT)
    if not found:
        if bridge.poll() is None:
            bridge.kill()
        raise LaunchError("rviz2: the foxglove bridge it started did not come up (its "
                          "output is above)")
    return bridge, found[0]
