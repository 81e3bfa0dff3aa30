"""Sensor benchmarks (issue 31): the lidar against raw `mj_multiRay` on the same scene.

A 32 × 1800 lidar (57,600 rays) in a scene of 40 obstacles. Raw: `mj_multiRay` on the
compiled world, in this process, one call a scan. Delivered: a real sim process, unpaced,
its lidar at update_rate 0 (a scan every step), a subscriber counting the scans it receives:
rays/s delivered against raw, same scene, same run. Then the same world paced at real time
(1 kHz physics) with the lidar at 10 Hz and subscribed: the sim's RTF from its clock.
"""

from __future__ import annotations

import os
import random
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _harness import start_router, summary, table

PY = sys.executable
HORIZONTAL, VERTICAL = 1800, 32
RAYS = HORIZONTAL * VERTICAL


def lidar_world(folder: Path, rate: float) -> Path:
    rng = random.Random(7)
    obstacles = []
    for i in range(40):
        x, y = rng.uniform(-14, 14), rng.uniform(-14, 14)
        if abs(x) < 2 and abs(y) < 2:
            x += 4
        shape = f"<box><size>{rng.uniform(0.3, 2):.2f} {rng.uniform(0.3, 2):.2f} " \
                f"{rng.uniform(0.5, 3):.2f}</size></box>" if i % 2 else \
                f"<cylinder><radius>{rng.uniform(0.2, 1):.2f}</radius><length>" \
                f"{rng.uniform(0.5, 3):.2f}</length></cylinder>"
        obstacles.append(f"""<model name="o{i}"><static>true</static><pose>{x:.2f} {y:.2f} 1 0 0
{rng.uniform(0, 3):.2f}</pose><link name="l"><collision name="c"><geometry>{shape}</geometry>
</collision><visual name="v"><geometry>{shape}</geometry></visual></link></model>""")
    text = f"""<?xml version="1.0"?><sdf version="1.9"><world name="lidar_bench">
<physics name="1ms" type="ignored"><max_step_size>0.001</max_step_size></physics>
<plugin filename="gz-sim-sensors-system" name="gz::sim::systems::Sensors"/>
<model name="ground"><static>true</static><link name="l"><collision name="c"><geometry><plane>
<normal>0 0 1</normal><size>60 60</size></plane></geometry></collision></link></model>
{''.join(obstacles)}
<model name="scanner"><static>true</static><pose>0 0 1 0 0 0</pose><link name="link">
<collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision>
<sensor name="lidar" type="gpu_lidar"><topic>lidar</topic><update_rate>{rate}</update_rate>
<lidar><scan><horizontal><samples>{HORIZONTAL}</samples><min_angle>-3.14159</min_angle>
<max_angle>3.14159</max_angle></horizontal><vertical><samples>{VERTICAL}</samples>
<min_angle>-0.3</min_angle><max_angle>0.3</max_angle></vertical></scan>
<range><min>0.1</min><max>30</max></range></lidar></sensor></link></model>
</world></sdf>"""
    path = folder / f"lidar_{rate:g}.sdf"
    path.write_text(text)
    return path


def raw_rays_per_second(world: Path, seconds: float = 3.0) -> float:
    """mj_multiRay alone: the same rays from the same place on the same compiled scene."""
    import mujoco
    import numpy as np

    from launcher.sim.loading import load_world_file

    model = load_world_file(world).spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    site = model.site("scanner/link/sensor/lidar").id
    v, h = np.meshgrid(np.linspace(-0.3, 0.3, VERTICAL), np.linspace(-3.14159, 3.14159,
                                                                     HORIZONTAL), indexing="ij")
    directions = np.stack([np.cos(v) * np.cos(h), np.cos(v) * np.sin(h), np.sin(v)],
                          axis=-1).reshape(-1)
    dist, geom = np.zeros(RAYS), np.zeros(RAYS, dtype=np.int32)
    body = int(model.site_bodyid[site])
    scans, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        mujoco.mj_multiRay(model, data, data.site_xpos[site], directions, None, 1, body,
                           geom, dist, None, RAYS, 30.0)
        scans += 1
    return scans * RAYS / (time.perf_counter() - start)


def delivered(world: Path, env: dict[str, str], seconds: float, paced: bool
              ) -> tuple[float, float]:
    """(scans received per second, the sim's RTF) with a subscriber on the lidar."""
    from launcher.bus import keys
    from launcher.bus.node import Node

    args = ["-r", "-s", "-v", "1", *([] if paced else ["-z", "0"]), str(world)]
    sim = subprocess.Popen([PY, "-m", "launcher.nodes.sim", *args], env=env)
    node = Node("bench_sensors", argv=[], space=keys.SIM)
    try:
        scans: list[float] = []
        clocks: list[tuple[float, float]] = []
        clock = struct.Struct("<4xiI")

        def on_clock(payload: bytes) -> None:
            sec, nanosec = clock.unpack_from(payload)
            clocks.append((time.monotonic(), sec + nanosec * 1e-9))

        node.create_subscription("mujoco_sim/msg/LaserScan", "/lidar",
                                 lambda payload: scans.append(time.monotonic()), raw=True)
        node.create_subscription("mujoco_sim/msg/Clock", "/world/lidar_bench/clock", on_clock,
                                 raw=True)
        deadline = time.monotonic() + 60
        while not scans and time.monotonic() < deadline:
            node.spin_once(0.1)
        node.spin(1.0)
        scans.clear()
        clocks.clear()
        start = time.monotonic()
        node.spin(seconds)
        elapsed = time.monotonic() - start
        (wall0, sim0), (wall1, sim1) = clocks[0], clocks[-1]
        return len(scans) / elapsed, (sim1 - sim0) / (wall1 - wall0)
    finally:
        node.destroy_node()
        sim.terminate()
        sim.wait(10)


def main() -> None:
    env, router = start_router()
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-sensors-"))
    os.environ.setdefault("MUJOCO_GL", "egl")
    try:
        unpaced_world, paced_world = lidar_world(folder, 0), lidar_world(folder, 10)
        ratios, raws, delivered_rates = [], [], []
        for _ in range(3):  # interleaved: raw, then delivered, on the same scene
            raw = raw_rays_per_second(unpaced_world)
            rate, _ = delivered(unpaced_world, env, 6.0, paced=False)
            raws.append(raw / 1e6)
            delivered_rates.append(rate * RAYS / 1e6)
            ratios.append(rate * RAYS / raw)
        scans, rtf = delivered(paced_world, env, 10.0, paced=True)
        rows = [
            (f"raw mj_multiRay, {VERTICAL} x {HORIZONTAL} rays, 40 obstacles, M rays/s",
             "report", summary(raws)),
            ("lidar delivered to a subscriber, unpaced, M rays/s", "report",
             summary(delivered_rates)),
            ("delivered / raw rays/s (same run)", ">= 0.80", summary(ratios)),
            ("lidar at 10 Hz, subscribed: scans/s delivered", "10", f"{scans:.2f}"),
            ("sim RTF at 1 kHz with the 10 Hz lidar subscribed", ">= 0.98", f"{rtf:.3f}"),
        ]
        table("sensors: the lidar", rows)
    finally:
        router.terminate()
        router.wait(10)


if __name__ == "__main__":
    main()
