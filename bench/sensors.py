"""Sensor benchmarks (issue 31): the lidar against raw `mj_multiRay`, the camera against raw
`mujoco.Renderer`, each on the same scene in the same run.

Lidar: a 32 × 1800 lidar (57,600 rays) in a scene of 40 obstacles. Raw: `mj_multiRay` on the
compiled world, in this process, one call a scan. Delivered: a real sim process, unpaced,
its lidar at update_rate 0 (a scan every step), a subscriber counting the scans it receives:
rays/s delivered against raw. Then the same world paced at real time (1 kHz physics) with the
lidar at 10 Hz and subscribed: the sim's RTF from its clock.

Ten robots: ten diff-drive robots driving circles among walls, each with a 2D lidar (360
samples at 10 Hz) and an IMU (100 Hz, always on), the sim at real time (1 kHz physics): its
RTF with one lidar subscribed, then with all ten subscribed.

Camera: 640 × 480 RGB in the same scene with a shadow-casting light. Raw: `mujoco.Renderer`
drawing that camera in this process, as fast as it can. Delivered: a real sim at real time,
the camera always due (update_rate 0), its renderer process drawing as fast as it can, and a
subscriber counting frames: fps against raw, same run; then the camera asked for at 30 Hz, and
the sim's RTF meanwhile. Depth the same way.
"""

from __future__ import annotations

import itertools
import math
import os
import random
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import psutil
from _harness import start_router, summary, table

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))  # (the tests' Recorder)

PY = sys.executable
HORIZONTAL, VERTICAL = 1800, 32
RAYS = HORIZONTAL * VERTICAL


CAMERA = """<sensor name="camera" type="{kind}"><topic>camera</topic>
<update_rate>{rate}</update_rate><camera><horizontal_fov>1.2</horizontal_fov><image><width>640</width>
<height>480</height></image><clip><near>0.1</near><far>50</far></clip></camera></sensor>"""


def lidar_world(folder: Path, rate: float, camera: str = "") -> Path:
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
<range><min>0.1</min><max>30</max></range></lidar></sensor>{camera}</link></model>
<light type="directional" name="sun"><cast_shadows>true</cast_shadows><pose>0 0 10 0 0 0</pose>
<diffuse>0.8 0.8 0.8 1</diffuse><direction>-0.5 0.2 -0.9</direction></light>
</world></sdf>"""
    path = folder / f"lidar_{rate:g}_{'camera' if camera else 'plain'}.sdf"
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


def raw_frames_per_second(world: Path, depth: bool, seconds: float = 4.0) -> float:
    """mujoco.Renderer alone: the same camera of the same scene, as fast as it draws."""
    import mujoco

    from launcher.sim.world import World
    from tests.support.sim import Recorder

    os.environ["LAUNCHER_RENDERER"] = "none"
    try:
        world_ = World.from_path(world, Recorder())  # (the camera as the sim makes it)
    finally:
        del os.environ["LAUNCHER_RENDERER"]
    model, data = world_.model, world_.data
    mujoco.mj_forward(model, data)
    renderer = mujoco.Renderer(model, 480, 640)
    if depth:
        renderer.enable_depth_rendering()
    camera = model.camera("scanner/link/sensor/camera").id
    frames, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        renderer.update_scene(data, camera=camera)
        renderer.render()
        frames += 1
    renderer.close()
    return frames / (time.perf_counter() - start)


def delivered(world: Path, env: dict[str, str], seconds: float, paced: bool,
              topic: str = "/lidar", type_name: str = "mujoco_sim/msg/LaserScan"
              ) -> tuple[float, float]:
    """(messages received per second on `topic`, the sim's RTF) with a subscriber there."""
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

        node.create_subscription(type_name, topic,
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


ROBOTS = 10
ROBOT = """<model name="robot{i}"><pose>{x:.2f} {y:.2f} 0.1 0 0 {yaw:.2f}</pose>
<link name="chassis"><inertial><mass>4</mass><inertia><ixx>0.05</ixx><iyy>0.08</iyy>
<izz>0.1</izz></inertia></inertial><collision name="c"><geometry><box><size>0.5 0.3 0.1</size>
</box></geometry></collision><visual name="v"><geometry><box><size>0.5 0.3 0.1</size></box>
</geometry></visual>
<sensor name="lidar" type="gpu_lidar"><pose>0.1 0 0.1 0 0 0</pose><topic>robot{i}/scan</topic>
<update_rate>10</update_rate><lidar><scan><horizontal><samples>360</samples>
<min_angle>-3.14159</min_angle><max_angle>3.14159</max_angle></horizontal></scan>
<range><min>0.12</min><max>12</max></range></lidar></sensor>
<sensor name="imu" type="imu"><always_on>1</always_on><update_rate>100</update_rate>
<topic>robot{i}/imu</topic></sensor></link>
{wheels}
<link name="caster"><pose>-0.2 0 -0.05 0 0 0</pose><inertial><mass>0.1</mass><inertia>
<ixx>1e-4</ixx><iyy>1e-4</iyy><izz>1e-4</izz></inertia></inertial><collision name="c">
<geometry><sphere><radius>0.05</radius></sphere></geometry><surface><friction><ode><mu>0</mu>
<mu2>0</mu2></ode></friction></surface></collision></link>
<joint name="caster_joint" type="fixed"><parent>chassis</parent><child>caster</child></joint>
<plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">
<left_joint>left_joint</left_joint><right_joint>right_joint</right_joint>
<wheel_separation>0.36</wheel_separation><wheel_radius>0.1</wheel_radius></plugin>
</model>"""
WHEEL = """<link name="{side}"><pose>0.1 {y} 0 -1.5707963 0 0</pose><inertial><mass>0.5</mass>
<inertia><ixx>1e-3</ixx><iyy>1e-3</iyy><izz>2e-3</izz></inertia></inertial><collision name="c">
<geometry><cylinder><radius>0.1</radius><length>0.04</length></cylinder></geometry>
</collision></link><joint name="{side}_joint" type="revolute"><parent>chassis</parent>
<child>{side}</child><axis><xyz>0 0 1</xyz></axis></joint>"""


def fleet_world(folder: Path) -> Path:
    """Ten robots on a ring inside four walls."""
    robots = []
    for i in range(ROBOTS):
        angle = 2 * math.pi * i / ROBOTS
        wheels = WHEEL.format(side="left", y=0.18) + WHEEL.format(side="right", y=-0.18)
        robots.append(ROBOT.format(i=i, x=4 * math.cos(angle), y=4 * math.sin(angle),
                                   yaw=angle + math.pi / 2, wheels=wheels))
    walls = "".join(
        f"""<model name="wall{n}"><static>true</static><pose>{x} {y} 0.5 0 0 {yaw}</pose>
<link name="l"><collision name="c"><geometry><box><size>16 0.2 1</size></box></geometry>
</collision></link></model>""" for n, (x, y, yaw) in
        enumerate([(8, 0, 1.5708), (-8, 0, 1.5708), (0, 8, 0), (0, -8, 0)]))
    text = f"""<?xml version="1.0"?><sdf version="1.9"><world name="fleet">
<physics name="1ms" type="ignored"><max_step_size>0.001</max_step_size></physics>
<plugin filename="gz-sim-sensors-system" name="gz::sim::systems::Sensors"/>
<plugin filename="gz-sim-imu-system" name="gz::sim::systems::Imu"/>
<model name="ground"><static>true</static><link name="l"><collision name="c"><geometry><plane>
<normal>0 0 1</normal><size>40 40</size></plane></geometry></collision></link></model>
{walls}{''.join(robots)}
</world></sdf>"""
    path = folder / "fleet.sdf"
    path.write_text(text)
    return path


def fleet(world: Path, env: dict[str, str], seconds: float) -> list[tuple[float, float]]:
    """(the sim's RTF, lidar scans/s per subscribed lidar) with one lidar subscribed, then
    with all ten, every robot driving a circle."""
    from launcher.bus import keys
    from launcher.bus.node import Node

    sim = subprocess.Popen([PY, "-m", "launcher.nodes.sim", "-r", "-s", "-v", "1", str(world)],
                           env=env)
    node = Node("bench_fleet", argv=[], space=keys.SIM)
    try:
        drive = [node.create_publisher("mujoco_sim/msg/Twist", f"/model/robot{i}/cmd_vel")
                 for i in range(ROBOTS)]
        command = node.message("mujoco_sim/msg/Twist")
        command.linear.x, command.angular.z = 0.5, 0.125  # a 4 m circle

        def go() -> None:
            for publisher in drive:
                publisher.publish(command)

        node.create_timer(0.5, go)
        clocks: list[tuple[float, float]] = []
        layout = struct.Struct("<4xiI")

        def on_clock(payload: bytes) -> None:
            sec, nanosec = layout.unpack_from(payload)
            clocks.append((time.monotonic(), sec + nanosec * 1e-9))

        node.create_subscription("mujoco_sim/msg/Clock", "/world/fleet/clock", on_clock,
                                 raw=True, inline=True)
        odometry: list[tuple[float, float]] = []
        node.create_subscription("mujoco_sim/msg/Odometry", "/model/robot0/odometry",
                                 lambda m: odometry.append((m.pose.position.x,
                                                            m.pose.position.y)))
        results, held = [], []
        scans: list[float] = []
        process = psutil.Process(sim.pid)
        for watched in (1, ROBOTS):
            for i in range(len(held), watched):
                held.append(node.create_subscription(
                    "mujoco_sim/msg/LaserScan", f"/robot{i}/scan",
                    lambda payload: scans.append(time.monotonic()), raw=True))
            node.spin(3.0)  # settle: subscribers found, robots moving
            clocks.clear()
            scans.clear()
            odometry.clear()
            cpu = process.cpu_times()
            node.spin(seconds)
            used = sum(process.cpu_times()[:2]) - sum(cpu[:2])
            (wall0, sim0), (wall1, sim1) = clocks[0], clocks[-1]
            path = sum(math.dist(a, b) for a, b in itertools.pairwise(odometry))
            results.append(((sim1 - sim0) / (wall1 - wall0), len(scans) / seconds / watched,
                            path / (sim1 - sim0), used / seconds))
        return results
    finally:
        node.destroy_node()
        sim.terminate()
        sim.wait(10)


def main() -> None:
    only = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else ""
    env, router = start_router()
    folder = Path(tempfile.mkdtemp(prefix="launcher-bench-sensors-"))
    os.environ.setdefault("MUJOCO_GL", "egl")
    try:
        unpaced_world, paced_world = lidar_world(folder, 0), lidar_world(folder, 10)
        lidar = only in ("", "lidar")
        ratios, raws, delivered_rates = [], [], []
        for _ in range(3 if lidar else 0):  # interleaved: raw, then delivered
            raw = raw_rays_per_second(unpaced_world)
            rate, _ = delivered(unpaced_world, env, 6.0, paced=False)
            raws.append(raw / 1e6)
            delivered_rates.append(rate * RAYS / 1e6)
            ratios.append(rate * RAYS / raw)
        scans, rtf = delivered(paced_world, env, 10.0, paced=True) if lidar else \
            (math.nan, math.nan)
        camera_rows = []
        for kind in ("camera", "depth_camera") if only in ("", "camera") else ():
            label = "RGB" if kind == "camera" else "depth"
            paced_camera = lidar_world(folder, 10, CAMERA.format(kind=kind, rate=30))
            flat_out = lidar_world(folder, 0, CAMERA.format(kind=kind, rate=0))
            raw_fps, throughput, ratio, fps, rtfs = [], [], [], [], []
            for _ in range(2):  # interleaved: raw, then delivered, on the same scene
                raw = raw_frames_per_second(flat_out, kind == "depth_camera")
                most, _ = delivered(flat_out, env, 8.0, paced=True, topic="/camera",
                                    type_name="mujoco_sim/msg/Image")
                raw_fps.append(raw)
                throughput.append(most)
                ratio.append(most / raw)
                got, camera_rtf = delivered(paced_camera, env, 8.0, paced=True,
                                            topic="/camera", type_name="mujoco_sim/msg/Image")
                fps.append(got)
                rtfs.append(camera_rtf)
            camera_rows += [
                (f"raw mujoco.Renderer, 640 x 480 {label}, fps", "report", summary(raw_fps)),
                (f"{label} camera at update_rate 0 (always due): fps delivered", "report",
                 summary(throughput)),
                ("delivered / raw fps (same run)", ">= 0.80",
                 summary(ratio)),
                (f"{label} camera asked for at 30 Hz, sim at real time: fps delivered", "30",
                 summary(fps)),
                (f"sim RTF while the {label} camera renders at 30 Hz", ">= 0.95",
                 summary(rtfs))]
        if lidar:
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
        if only in ("", "camera"):
            table("sensors: the camera", camera_rows)
        if only in ("", "fleet"):
            runs = [fleet(fleet_world(folder), env, 10.0) for _ in range(2)]
            table("sensors: ten robots", [
                ("RTF, 10 robots driving, 10 lidars (360 @ 10 Hz) + 10 IMUs (100 Hz), one "
                 "lidar subscribed", ">= 0.95", summary([r[0][0] for r in runs])),
                ("  scans/s the subscribed lidar delivers", "10",
                 summary([r[0][1] for r in runs])),
                ("RTF, the same with all ten lidars subscribed", "report",
                 summary([r[1][0] for r in runs])),
                ("  scans/s each lidar delivers", "10", summary([r[1][1] for r in runs])),
                ("  robot0's speed from its odometry, m/s (0.5 asked: they drive)", "report",
                 summary([r[1][2] for r in runs])),
                ("  the sim's CPU, cores (one lidar subscribed; all ten)", "report",
                 f"{summary([r[0][3] for r in runs])}; {summary([r[1][3] for r in runs])}")])
    finally:
        router.terminate()
        router.wait(10)


if __name__ == "__main__":
    main()
