"""Sim benchmarks (issue 5): unpaced speed vs raw mj_step, pacing, spawn latency, create.

Unpaced: the world server's own loop (plugins, clock and state publishing on a real bus) in
this process, against `mujoco.mj_step` called once per step on the same model and state.
Paced: a real sim process at real time (1 kHz physics, one robot), its RTF from its clock
messages and its CPU from the kernel. Spawn latency: create service call → response, when
the entity is compiled into the world that the next step advances.
"""

from __future__ import annotations

import argparse
import os
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import psutil
from _harness import start_router, summary, table

PY = sys.executable
ROBOT = Path(__file__).resolve().parent.parent / "tests" / "data" / "diffbot.urdf"
DESCRIPTION = """
import sys
from pathlib import Path
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
node = Node("robot_state_publisher")
node.create_publisher("std_msgs/msg/String", "robot_description", LATCHED).publish(
    node.message("std_msgs/msg/String", data=Path(sys.argv[1]).read_text()))
print("ready", flush=True)
node.spin()
"""


def quiet_transport(node):
    from launcher.sim.transport import BusTransport

    transport = BusTransport(node)
    transport.logger.threshold = 40
    return transport


def demo_robot() -> str:
    """The demo's robot as its launch file makes it (xacro, with its Gazebo plugins)."""
    from launcher.packages.index import PackageIndex
    from launcher.packages.xacro import run_xacro

    index = PackageIndex.from_environment()
    urdf = run_xacro(["xacro", str(index.share("robot_description") / "urdf" / "robot.xacro")],
                     index)
    assert urdf is not None
    path = Path(tempfile.mkdtemp()) / "robot.urdf"
    path.write_text(urdf)
    return str(path)


def unpaced(robots: int, steps: int, demo: bool = False) -> tuple[float, float]:
    """(server steps/s, raw mj_step steps/s) on the same model and state: the empty world
    with the test robot, or (`demo`) the seed's SDF world with the demo's robot."""
    import mujoco

    from launcher.bus import keys
    from launcher.bus.node import Node
    from launcher.sim import mjcf
    from launcher.sim.resources import find_world
    from launcher.sim.server import SimServer
    from launcher.sim.transform import pose_from
    from launcher.sim.world import World

    node = Node(f"bench_sim_{robots}", argv=[], space=keys.SIM)
    if demo:
        from launcher.packages.index import PackageIndex

        share = PackageIndex.from_environment().share("robot_gazebo")
        os.environ["GZ_SIM_SYSTEM_PLUGIN_PATH"] = str(share / "plugins")  # (its hooks')
        os.environ["GZ_SIM_RESOURCE_PATH"] = f"{share / 'models'}:{share / 'worlds'}"
        world = World.from_path(share / "worlds" / "robot.world", quiet_transport(node))
        template = world.templates.from_file(demo_robot())
    else:
        path = find_world("empty.xml")
        source = mjcf.read(path.read_text(), path)
        world = World(mjcf.compile_spec(source), str(path), quiet_transport(node),
                      source.plugins)
        template = world.templates.from_file(str(ROBOT))
    server = SimServer(world, node, rtf=0.0, running=True)
    for i in range(robots):
        position, quat = pose_from([0.0, i * 1.0, 0.1 if demo else 0.06, 0, 0, 0])
        world.spawn(template, f"r{i}", position, quat)
    server.run(world.physics.iterations + 500)  # settle
    qpos, qvel = world.data.qpos.copy(), world.data.qvel.copy()
    start = time.perf_counter()
    server.run(world.physics.iterations + steps)
    served = steps / (time.perf_counter() - start)
    data = mujoco.MjData(world.model)
    data.qpos[:], data.qvel[:] = qpos, qvel
    model = world.model
    start = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    raw = steps / (time.perf_counter() - start)
    node.destroy_node()
    return served, raw


def paced(env: dict[str, str], seconds: float) -> dict[str, float]:
    from launcher.bus import keys
    from launcher.bus.node import Node

    sim = subprocess.Popen([PY, "-m", "launcher.nodes.sim", "-r"], env=env)
    node = Node("bench_probe", argv=[], space=keys.SIM)  # the sim's own side
    try:
        create = subprocess.run([PY, "-m", "launcher.nodes.create", "-name", "bot", "-file",
                                 str(ROBOT), "-z", "0.06"], env=env, capture_output=True,
                                text=True)
        assert create.returncode == 0, create.stderr
        clocks: list[tuple[float, float]] = []
        clock = struct.Struct("<4xiI")  # sim time, the first field: read without decoding

        def on_clock(payload: bytes) -> None:
            sec, nanosec = clock.unpack_from(payload)
            clocks.append((time.monotonic(), sec + nanosec * 1e-9))

        node.create_subscription("mujoco_sim/msg/Clock", "/world/empty/clock", on_clock,
                                 raw=True)
        node.spin(2.0)
        process = psutil.Process(sim.pid)
        cpu0, clocks[:] = sum(process.cpu_times()[:2]), []
        node.spin(seconds)
        cpu = (sum(process.cpu_times()[:2]) - cpu0) / seconds
        (wall0, sim0), (wall1, sim1) = clocks[0], clocks[-1]
        figures = {"rtf": (sim1 - sim0) / (wall1 - wall0), "cpu": cpu * 100}
        figures.update(spawn_latency(node))
        return figures
    finally:
        node.destroy_node()
        sim.terminate()
        sim.wait(10)


def spawn_latency(node) -> dict[str, float]:
    client = node.create_client("mujoco_sim/srv/Create", "/world/empty/create")
    remover = node.create_client("mujoco_sim/srv/Remove", "/world/empty/remove")
    text = ROBOT.read_text()
    present = 1  # "bot" from the paced run
    figures = {}

    def spawn(name: str, y: float) -> float:
        request = node.message("mujoco_sim/srv/Create_Request", name=name, sdf=text,
                               pose={"position": {"y": y, "z": 0.06},
                                     "orientation": {"w": 1.0}})
        start = time.perf_counter()
        response = client.call(request, timeout=30)
        elapsed = time.perf_counter() - start
        assert response.success, response.message
        return elapsed

    remover.call(node.message("mujoco_sim/srv/Remove_Request", name="bot"), timeout=30)
    present = 0
    for target in (0, 10, 50):
        while present < target:
            spawn(f"r{present}", 1.0 + present)
            present += 1
        samples = []
        for attempt in range(5):
            samples.append(spawn(f"probe{attempt}", -2.0))
            remover.call(node.message("mujoco_sim/srv/Remove_Request", name=f"probe{attempt}"),
                         timeout=30)
        figures[f"spawn{target}"] = sorted(samples)[len(samples) // 2]
    return figures


def create_from_topic(env: dict[str, str], runs: int) -> list[float]:
    sim = subprocess.Popen([PY, "-m", "launcher.nodes.sim", "-r"], env=env)
    publisher = subprocess.Popen([PY, "-c", DESCRIPTION, str(ROBOT)], env=env,
                                 stdout=subprocess.PIPE, text=True)
    try:
        assert publisher.stdout is not None and "ready" in publisher.stdout.readline()
        times = []
        for i in range(runs):
            start = time.perf_counter()
            done = subprocess.run([PY, "-m", "launcher.nodes.create", "-entity", f"robot{i}",
                                   "-topic", "robot_description", "-y", str(i)], env=env,
                                  capture_output=True, text=True)
            times.append(time.perf_counter() - start)
            assert done.returncode == 0, done.stderr
        return times
    finally:
        for proc in (publisher, sim):
            proc.terminate()
            proc.wait(10)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=30.0, help="length of the paced run")
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    env, router = start_router()
    try:
        one = [unpaced(1, 20000) for _ in range(3)]
        ten = [unpaced(10, 5000) for _ in range(3)]
        demo_one = [unpaced(1, 20000, demo=True) for _ in range(3)]
        demo_ten = [unpaced(10, 5000, demo=True) for _ in range(3)]
        pace = paced(env, args.seconds)
        creates = create_from_topic(env, args.runs)
    finally:
        router.terminate()
        router.wait()

    def ratio(pairs):
        return summary([100 * served / raw for served, raw in pairs])

    table("sim (rates in steps/s; times in seconds)", [
        ("unpaced, 1 robot: server steps/s", "report", summary([s for s, _ in one])),
        ("unpaced, 1 robot: raw mj_step steps/s", "report", summary([r for _, r in one])),
        ("unpaced, 1 robot: server % of raw", ">= 85", ratio(one)),
        ("unpaced, 10 robots: server steps/s", "report", summary([s for s, _ in ten])),
        ("unpaced, 10 robots: raw mj_step steps/s", "report", summary([r for _, r in ten])),
        ("unpaced, 10 robots: server % of raw", ">= 85", ratio(ten)),
        ("unpaced, demo world + robot: server % of raw", ">= 85", ratio(demo_one)),
        ("unpaced, demo world + 10 robots: server % of raw", ">= 85", ratio(demo_ten)),
        (f"paced 1 kHz, 1 robot, {args.seconds:g} s: RTF", "1.00 +- 0.01", f"{pace['rtf']:.4f}"),
        (f"paced 1 kHz, 1 robot, {args.seconds:g} s: CPU %", "<= 20", f"{pace['cpu']:.1f}"),
        ("spawn latency, 0 robots present", "report", f"{pace['spawn0']:.4f}"),
        ("spawn latency, 10 robots present", "<= 0.030", f"{pace['spawn10']:.4f}"),
        ("spawn latency, 50 robots present", "report", f"{pace['spawn50']:.4f}"),
        ("create -topic robot_description, end to end", "report", summary(creates)),
    ])


if __name__ == "__main__":
    main()
