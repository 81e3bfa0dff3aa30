#!/usr/bin/env python3
"""Large messages between two processes of one host, through the graph's router (issue 57):
Zenoh's shared memory against the same link without it, in the same run.

The sizes are the sensors' frames: a 640 × 480 RGB image (0.9 MB), a 640 × 480 depth image
(1.2 MB) and its point cloud (32 bytes a point, 9.8 MB). A sender process puts one frame as
fast as it can for `--seconds`; a receiver process takes each frame's bytes (as a subscriber
deserialising it does) and counts them. Figures: frames received per second, and GB/s.

- `launcher's bus`: sessions opened as nodes open theirs (bus/session.py), through a router
  started as launches start it. Zenoh's transport optimisation puts a message over 3 KB in
  shared memory by itself (on by default, and launcher keeps it on);
- `without shared memory`: the same router and sessions with `transport/shared_memory`
  turned off: every frame copied through the router's Unix sockets.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from _harness import start_router, stop, table

SIZES = {"RGB 640 x 480": 640 * 480 * 3, "depth 640 x 480": 640 * 480 * 4,
         "point cloud 640 x 480": 640 * 480 * 32}
PEER = """
import os, sys, time
import zenoh
from launcher.bus import session as bus

role, size, seconds, shm = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
original = bus.config


def config(*args, **kwargs):
    settings = original(*args, **kwargs)
    if shm == "off":
        settings.insert_json5("transport/shared_memory/enabled", "false")
    return settings


bus.config = config
session = bus.open_session()
if role == "send":
    publisher = session.declare_publisher("bench/frames",
                                          congestion_control=zenoh.CongestionControl.DROP)
    frame = os.urandom(size)
    time.sleep(1.0)  # (the receiver's subscription known to the router)
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        publisher.put(frame)
else:
    got = []
    subscriber = session.declare_subscriber(
        "bench/frames",
        lambda sample: got.append((time.monotonic(), len(sample.payload.to_bytes()))))
    print("ready", flush=True)
    time.sleep(seconds + 2.0)
    span = got[-1][0] - got[0][0] if len(got) > 1 else 0.0
    rate = (len(got) - 1) / span if span else 0.0
    print(f"{rate:.1f}", flush=True)
session.close()
"""


def frames_per_second(script: Path, env: dict[str, str], size: int, seconds: float,
                      shm: str) -> float:
    receiver = subprocess.Popen([sys.executable, str(script), "receive", str(size),
                                 str(seconds), shm], env=env, stdout=subprocess.PIPE, text=True)
    try:
        assert receiver.stdout.readline().strip() == "ready"  # type: ignore[union-attr]
        subprocess.run([sys.executable, str(script), "send", str(size), str(seconds), shm],
                       env=env, check=True)
        return float(receiver.stdout.readline())  # type: ignore[union-attr]
    finally:
        receiver.wait(30)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=3.0)
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-shm-"))
    script = folder / "peer.py"
    script.write_text(PEER)
    env, router = start_router()
    rows = []
    try:
        for name, size in SIZES.items():
            on = frames_per_second(script, env, size, args.seconds, "on")
            off = frames_per_second(script, env, size, args.seconds, "off")
            rows += [(f"{name} ({size / 1e6:.1f} MB), launcher's bus: frames/s", "report",
                      f"{on:.0f} ({on * size / 1e9:.2f} GB/s)"),
                     (f"{name}, without shared memory: frames/s", "report",
                      f"{off:.0f} ({off * size / 1e9:.2f} GB/s)"),
                     (f"{name}: launcher's bus / without shared memory", "report",
                      f"{on / off:.1f}x" if off else "-")]
    finally:
        stop(router)
        shutil.rmtree(folder, ignore_errors=True)
        shutil.rmtree(env["LAUNCHER_RUN_DIR"], ignore_errors=True)
    table("Large messages between two processes through the router", rows)


if __name__ == "__main__":
    main()
