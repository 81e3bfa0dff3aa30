#!/usr/bin/env python3
"""The user's hand on a running launch (issue 56; bench/control.py is ros2_control's):

- `launcher restart NAME` → the node's first message again, against the same node started
  alone (`launcher launch` of it): the time from the command to the first message of the new
  process, as a subscriber on the graph hears it;
- `launcher ps` with 100 processes running: the command's wall time, as a user waits for it.

Everything is real: the launch, its node, the CLI, the graph. Medians of `--runs`.

    python bench/launch_control.py [--runs 5]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

from _harness import launcher_cmd, start_router, table

TALKER = """
import os
from launcher.bus.node import Node
node = Node("talker")
publisher = node.create_publisher("std_msgs/msg/String", "chatter", 10)
message = node.message("std_msgs/msg/String", data=str(os.getpid()))
node.create_timer(0.01, lambda: publisher.publish(message))
node.spin()
"""


class Heard:
    """The pids /chatter's messages come from, and when each was first heard."""

    def __init__(self) -> None:
        from launcher.bus.node import Node

        self.node = Node("bench_listener", argv=[])
        self.first: dict[str, float] = {}
        self.lock = threading.Lock()
        self.node.create_subscription("std_msgs/msg/String", "/chatter", self._got, inline=True)

    def _got(self, message) -> None:
        with self.lock:
            self.first.setdefault(message.data, time.perf_counter())

    def new_after(self, known: set[str], timeout: float = 30.0) -> float:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.lock:
                fresh = [t for pid, t in self.first.items() if pid not in known]
            if fresh:
                return min(fresh)
            time.sleep(0.001)
        raise TimeoutError("no new talker was heard")


def launch(folder: Path, text: str, env: dict[str, str]) -> subprocess.Popen:
    path = folder / f"l{time.monotonic_ns()}.launch.yaml"
    path.write_text(text)
    return subprocess.Popen([*launcher_cmd(), "launch", "-n", str(path)], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def ps_ready(env: dict[str, str], needle: str, timeout: float = 60.0) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        out = subprocess.run([*launcher_cmd(), "ps"], env=env, capture_output=True,
                             text=True).stdout
        if needle in out:
            return
        time.sleep(0.2)
    raise TimeoutError(f"{needle} never listed")


def stop(proc: subprocess.Popen) -> None:
    proc.send_signal(2)
    try:
        proc.wait(30)
    except subprocess.TimeoutExpired:
        proc.kill()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-control-"))
    env, router = start_router()
    env = {**env, "LAUNCHER_LOG_DIR": str(folder / "log")}
    os.environ.update(env)
    (folder / "talker.py").write_text(TALKER)
    talker = f'launch:\n  - executable: {{cmd: "{sys.executable} {folder}/talker.py", ' \
             f'name: talker}}\n'
    heard = Heard()
    restart, alone = [], []
    try:
        proc = launch(folder, talker, env)
        ps_ready(env, "talker-1")
        heard.new_after(set())
        for _ in range(args.runs):
            known = set(heard.first)
            began = time.perf_counter()
            subprocess.run([*launcher_cmd(), "restart", "talker"], env=env, check=True,
                           stdout=subprocess.DEVNULL)
            restart.append(heard.new_after(known) - began)
        stop(proc)
        for _ in range(args.runs):
            known = set(heard.first)
            began = time.perf_counter()
            proc = launch(folder, talker, env)
            alone.append(heard.new_after(known) - began)
            stop(proc)
        many = "launch:\n" + "".join("  - executable: {cmd: sleep 600}\n" for _ in range(100))
        proc = launch(folder, many, env)
        ps_ready(env, "sleep-100")
        times = []
        for _ in range(max(args.runs, 10)):
            began = time.perf_counter()
            subprocess.run([*launcher_cmd(), "ps"], env=env, check=True,
                           stdout=subprocess.DEVNULL)
            times.append(time.perf_counter() - began)
        stop(proc)
    finally:
        heard.node.destroy_node()
        router.terminate()
        router.wait(10)
    r, a, p = statistics.median(restart), statistics.median(alone), statistics.median(times)
    table("The user's hand on a running launch", [
        ("restart → the node's first message again (s)", "-", f"{r:.3f}"),
        ("the node launched alone → its first message (s)", "-", f"{a:.3f}"),
        ("restart / launched alone", "≤ 1", f"{r / a:.2f}"),
        ("launcher ps with 100 processes (s)", "-", f"{p:.3f}"),
    ])


if __name__ == "__main__":
    main()
